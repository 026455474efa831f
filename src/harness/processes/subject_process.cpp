#include "harness/processes/subject_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>
#include <type_traits>
#include <utility>

#include "harness/formats/case_file.h"
#include "harness/formats/input_json.h"
#include "harness/formats/mesh_files.h"
#include "harness/formats/sha256.h"
#include "harness/model/mesh_query.h"
#include "harness/model/subject_binding.h"
#include "harness/formats/write_all.h"
#include "harness/processes/child.h"

namespace cc::harness {
namespace {

using Clock = std::chrono::steady_clock;

// A server's descriptors: 0 /dev/null, 1 and 2 files of its own, then its two pipes; no other.
constexpr int kQuestions = 3, kAnswers = 4, kKept = 5;
constexpr std::array<const char*, kKept> kDescriptorNames = {"standard input", "standard output", "standard error",
                                                             "crosscheck's questions", "its answers to crosscheck"};
// Each message is framed: 4 bytes of magic, 4 of length (both little-endian), then JSON text.
constexpr std::uint32_t kQuestionMagic = 0x51434343, kAnswerMagic = 0x41434343;  // "CCCQ", "CCCA"
constexpr std::uint32_t kMaxFrame = 1u << 30;
// A server's exit status when it ends itself, having said why in its notes.
constexpr int kServerGaveUp = 81;

// What a server tells its client in memory they share, readable after the server's end.
struct ServerNotes {
  std::atomic<int> in_call{0};  // 1 while the subject's function runs
  char last_words[480] = {};    // why it ended itself
};

void say(ServerNotes& notes, const std::string& words) {
  std::snprintf(notes.last_words, sizeof notes.last_words, "%s", words.c_str());
}

std::string framed(std::uint32_t magic, const std::string& payload) {
  std::string out(8, '\0');
  const auto length = static_cast<std::uint32_t>(payload.size());
  for (int i = 0; i < 4; ++i) {
    out[static_cast<std::size_t>(i)] = static_cast<char>(magic >> (8 * i));
    out[static_cast<std::size_t>(4 + i)] = static_cast<char>(length >> (8 * i));
  }
  return out + payload;
}

std::uint32_t word_at(const char* p) {
  std::uint32_t w = 0;
  for (int i = 3; i >= 0; --i) w = w << 8 | static_cast<unsigned char>(p[i]);
  return w;
}

// Reads exactly n bytes, blocking; false at the end of the pipe or on an error.
bool read_exactly(int fd, char* to, std::size_t n) {
  while (n > 0) {
    const ssize_t got = ::read(fd, to, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    to += got, n -= static_cast<std::size_t>(got);
  }
  return true;
}

// The same with a deadline: how the client waits for an answer.
enum class Read { whole, ended, timed_out };
Read read_until(int fd, char* to, std::size_t n, Clock::time_point deadline) {
  while (n > 0) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return Read::timed_out;
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno != EINTR) return Read::ended;
    if (ready <= 0) continue;
    const ssize_t got = ::read(fd, to, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return Read::ended;
    to += got, n -= static_cast<std::size_t>(got);
  }
  return Read::whole;
}

// Writes to a pipe whose reader may have ended: EPIPE is an error, not a SIGPIPE that ends the
// caller (a SIGPIPE raised here is taken before the signal mask is restored).
bool write_to_pipe(int fd, const std::string& bytes) {
  sigset_t pipe_signal, before;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &before);
  const bool ok = write_all(fd, bytes);
  if (!ok && errno == EPIPE) {
    const timespec none{0, 0};
    while (sigtimedwait(&pipe_signal, nullptr, &none) == SIGPIPE) {
    }
  }
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
  return ok;
}

// --- The server, in the child -------------------------------------------------------------------

struct DescriptorId {
  dev_t device = 0;
  ino_t inode = 0;
};

std::array<DescriptorId, kKept> descriptor_ids() {
  std::array<DescriptorId, kKept> ids{};
  for (int fd = 0; fd < kKept; ++fd) {
    struct stat s {};
    if (::fstat(fd, &s) == 0) ids[static_cast<std::size_t>(fd)] = {s.st_dev, s.st_ino};
  }
  return ids;
}

// The first of the server's descriptors that the subject closed or replaced, said; or nothing.
std::string damaged_descriptor(const std::array<DescriptorId, kKept>& ids) {
  for (int fd = 0; fd < kKept; ++fd) {
    struct stat s {};
    const auto& id = ids[static_cast<std::size_t>(fd)];
    const char* what = ::fstat(fd, &s) != 0 ? "closed" : (s.st_dev != id.device || s.st_ino != id.inode ? "replaced" : nullptr);
    if (what != nullptr) {
      return std::string(what) + " file descriptor " + std::to_string(fd) + " (" + kDescriptorNames[static_cast<std::size_t>(fd)] +
             "), which it does not own";
    }
  }
  return {};
}

// Sets up the server's descriptors (above); false when one cannot be made.
bool server_descriptors(int questions, int answers) {
  std::FILE* out = std::tmpfile();
  std::FILE* err = std::tmpfile();
  const int null = ::open("/dev/null", O_RDONLY);
  if (out == nullptr || err == nullptr || null < 0) return false;
  // Above every target first, so that no dup2 below overwrites a source.
  const std::array<int, kKept> from = {::fcntl(null, F_DUPFD, 16), ::fcntl(::fileno(out), F_DUPFD, 16),
                                       ::fcntl(::fileno(err), F_DUPFD, 16), ::fcntl(questions, F_DUPFD, 16),
                                       ::fcntl(answers, F_DUPFD, 16)};
  for (int fd = 0; fd < kKept; ++fd) {
    if (from[static_cast<std::size_t>(fd)] < 0 || ::dup2(from[static_cast<std::size_t>(fd)], fd) != fd) return false;
  }
  ::close_range(kKept, ~0u, 0);  // the stdio streams of the two files are never used again
  return true;
}

[[noreturn]] void serve(const std::string& path, int questions, int answers, ServerNotes& notes, pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // it never outlives the process it answers
  if (::getppid() != parent) std::_Exit(kServerGaveUp);
  std::signal(SIGINT, SIG_IGN);  // the terminal's Ctrl-C is for the caller to judge
  std::signal(SIGTERM, SIG_DFL);
  std::signal(SIGPIPE, SIG_DFL);
  if (!server_descriptors(questions, answers)) {
    say(notes, "crosscheck could not set up the subject's process: " + std::string(std::strerror(errno)));
    std::_Exit(kServerGaveUp);
  }
  SubjectBinding subject;
  try {
    subject = SubjectBinding::open(path);
  } catch (const std::exception& e) {
    say(notes, std::string("could not be opened again: ") + e.what());
    std::_Exit(kServerGaveUp);
  }
  std::fflush(nullptr);
  (void)take_captured_line(STDOUT_FILENO), (void)take_captured_line(STDERR_FILENO);  // what it said while loading
  const auto ids = descriptor_ids();
  for (;;) {
    char header[8];
    if (!read_exactly(kQuestions, header, sizeof header)) std::_Exit(0);  // the client is done
    const std::uint32_t length = word_at(header + 4);
    std::string question(length <= kMaxFrame ? length : 0, '\0');
    if (word_at(header) != kQuestionMagic || length > kMaxFrame || !read_exactly(kQuestions, question.data(), length)) {
      say(notes, "file descriptor 3 (crosscheck's questions), which it does not own, was read from or damaged");
      std::_Exit(kServerGaveUp);
    }
    Json reply;
    Input input;
    try {
      const Json q = Json::parse(question);
      const auto kind = query_kind_named(q.at("kind").get<std::string>());
      if (!kind) throw std::runtime_error("no such query kind");
      input = input_from_json(*kind, q.at("input"), "/input");
    } catch (const std::exception& e) {  // crosscheck's fault, not the subject's
      reply = {{"error", std::string("the question could not be read: ") + e.what()}};
    }
    if (reply.is_null()) {
      notes.in_call = 1;
      try {
        reply = {{"answer", answer_json(subject.ask(input))}};
      } catch (const std::exception& e) {
        reply = {{"failure", e.what()}};
      }
      notes.in_call = 0;
      std::fflush(nullptr);  // what it printed through stdio, into the files now
      if (const std::string damage = damaged_descriptor(ids); !damage.empty()) {
        say(notes, damage);
        std::_Exit(kServerGaveUp);
      }
      for (const int fd : {STDOUT_FILENO, STDERR_FILENO}) {
        const auto said = take_captured_line(fd);
        if (!said || reply.contains("printed")) continue;
        const std::string where = kDescriptorNames[static_cast<std::size_t>(fd)];
        if (!reply.contains("failure")) reply = {{"failure", "wrote to " + where + ": \"" + *said + "\""}};
        reply["printed"] = where + ": " + *said;
      }
    }
    // A message of the subject's (a loader's, a path) may hold bytes that are not UTF-8.
    const std::string text = reply.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (!write_to_pipe(kAnswers, framed(kAnswerMagic, text))) {
      say(notes, "file descriptor 4 (its answers to crosscheck), which it does not own, cannot be written to");
      std::_Exit(kServerGaveUp);
    }
  }
}

// --- The client ---------------------------------------------------------------------------------

// Each mesh file named in the input, as written, with the path this process read it from: the
// server, whose folder may be another, reads the same file.
Json question_input(const Input& input) {
  Json j = input_to_json(input);
  std::map<std::string, std::string> read_from;
  const auto note = [&](const MeshRef& m) {
    if (m.source != MeshRef::Source::file || m.mesh == nullptr) return;
    if (const auto path = mesh_file_of(*m.mesh)) read_from[m.file] = path->string();
  };
  std::visit(
      [&]<class In>(const In& in) {
        if constexpr (requires { in.mesh; }) {
          if constexpr (std::is_same_v<std::decay_t<decltype(in.mesh)>, MeshRef>) note(in.mesh);
        }
        if constexpr (requires { in.meshes; }) note(in.meshes.a), note(in.meshes.b);
      },
      input);
  if (read_from.empty()) return j;
  const auto rewrite = [&](auto& self, Json& node) -> void {
    if (node.is_object() && node.contains("file") && node["file"].is_string()) {
      if (const auto it = read_from.find(node["file"].get<std::string>()); it != read_from.end()) node["file"] = it->second;
    }
    if (node.is_structured()) {
      for (Json& child : node) self(self, child);
    }
  };
  rewrite(rewrite, j);
  return j;
}

class IsolatedSubject final : public Subject {
 public:
  IsolatedSubject(std::string path, SubjectIdentity identity, double call_seconds)
      : path_(std::move(path)), identity_(std::move(identity)), call_seconds_(call_seconds) {}
  ~IsolatedSubject() override { end_server(); }

  const std::string& path() const override { return path_; }
  const SubjectIdentity& identity() const override { return identity_; }
  void set_call_seconds(double seconds) { call_seconds_ = seconds; }
  std::optional<std::string> take_printed() const { return std::exchange(printed_, std::nullopt); }
  void end_server_of_this_process() const {
    if (server_.owner == ::getpid()) (void)end_server();
    else forget_inherited_server();
  }

  Answer ask(const Input& input) const override {
    const QueryKind kind = kind_of(input);
    if (!answers(kind)) throw std::logic_error("the subject " + path_ + " does not answer " + std::string(name(kind)));
    if (server_.owner != ::getpid()) forget_inherited_server();
    if (server_.pid < 0) start_server();
    const std::string question = framed(kQuestionMagic, Json{{"kind", name(kind)}, {"input", question_input(input)}}.dump());
    if (!write_to_pipe(server_.questions, question)) throw SubjectFailure(end_server());
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(call_seconds_));
    char header[8];
    switch (read_until(server_.answers, header, sizeof header, deadline)) {
      case Read::timed_out: throw SubjectFailure(end_server(std::string(kTimedOut) + ": ran past its time limit of " + seconds_text() + " s"));
      case Read::ended: throw SubjectFailure(end_server());
      case Read::whole: break;
    }
    const std::uint32_t length = word_at(header + 4);
    if (word_at(header) != kAnswerMagic || length > kMaxFrame) {
      throw SubjectFailure(end_server("wrote to file descriptor 4 (its answers to crosscheck), which it does not own"));
    }
    std::string text(length, '\0');
    if (read_until(server_.answers, text.data(), length, deadline) != Read::whole) throw SubjectFailure(end_server());
    Json reply;
    try {
      reply = Json::parse(text);
    } catch (const Json::exception&) {
      throw SubjectFailure(end_server("wrote to file descriptor 4 (its answers to crosscheck), which it does not own"));
    }
    if (reply.contains("printed") && !printed_) printed_ = reply["printed"].get<std::string>();
    if (reply.contains("failure")) throw SubjectFailure(reply["failure"].get<std::string>());
    if (reply.contains("error")) throw std::runtime_error(reply["error"].get<std::string>());
    return answer_from_json(reply.at("answer"), "/answer");
  }

 private:
  struct Server {
    pid_t pid = -1;    // the server, a child of `owner`
    pid_t owner = 0;   // the process that started it
    int questions = -1, answers = -1;
    ServerNotes* notes = nullptr;
  };

  std::string seconds_text() const {
    char text[32];
    std::snprintf(text, sizeof text, "%g", call_seconds_);
    return text;
  }

  void start_server() const {
    int q[2], a[2];
    if (::pipe2(q, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
    if (::pipe2(a, O_CLOEXEC) != 0) {
      const int error = errno;
      ::close(q[0]), ::close(q[1]);
      throw std::system_error(error, std::generic_category(), "pipe");
    }
    void* shared = ::mmap(nullptr, sizeof(ServerNotes), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (shared == MAP_FAILED) {
      for (int fd : {q[0], q[1], a[0], a[1]}) ::close(fd);
      throw std::system_error(errno, std::generic_category(), "mmap");
    }
    auto* notes = new (shared) ServerNotes();
    std::fflush(nullptr);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0) serve(path_, q[0], a[1], *notes, parent);
    ::close(q[0]), ::close(a[1]);
    if (pid < 0) {
      const int error = errno;
      ::close(q[1]), ::close(a[0]), ::munmap(shared, sizeof(ServerNotes));
      throw std::system_error(error, std::generic_category(), "fork");
    }
    server_ = {pid, parent, q[1], a[0], notes};
  }

  // A forked process holds copies of its parent's server's pipes: they are not its to use.
  void forget_inherited_server() const {
    if (server_.pid >= 0) {
      ::close(server_.questions), ::close(server_.answers);
      ::munmap(server_.notes, sizeof(ServerNotes));
    }
    server_ = {};
  }

  // Ends the server and says how it ended: `why` when the client knows (a time limit, a
  // damaged answer: then it is killed at once), else what the server said before it ended, else
  // its exit. A server whose answers' channel closed may still be finding out why (a subject
  // that closed it): it is given a second to end by itself before it is killed.
  std::string end_server(std::string why = {}) const {
    if (server_.pid < 0 || server_.owner != ::getpid()) return why;
    ::close(server_.questions), ::close(server_.answers);
    if (!why.empty()) ::kill(server_.pid, SIGKILL);
    const ChildEnd end = finish_child(Child{server_.pid, -1, false}, 1);
    if (why.empty()) why = server_.notes->last_words;
    if (why.empty() && end.timed_out) {  // its answers' channel closed, the server still running
      why = "closed file descriptor 4 (its answers to crosscheck), which it does not own";
    }
    if (why.empty()) {
      why = end.signal != 0 ? "was killed by signal " + std::to_string(end.signal) + " (" + strsignal(end.signal) + ")"
                            : "exited with status " + std::to_string(end.status);
      if (server_.notes->in_call == 0) why += ", between calls";
    }
    ::munmap(server_.notes, sizeof(ServerNotes));
    server_ = {};
    return why;
  }

  std::string path_;
  SubjectIdentity identity_;
  double call_seconds_;
  mutable Server server_;
  mutable std::optional<std::string> printed_;  // the first line it printed since take_printed
};

}  // namespace

std::shared_ptr<Subject> load_subject(const std::string& path, double call_seconds, double load_seconds) {
  ChildEnd probe;
  try {
    probe = run_in_child(
        [&](int out) {
          // What its constructors print goes nowhere; its answer to the probe goes up the pipe.
          if (const int null = ::open("/dev/null", O_RDWR); null >= 0) ::dup2(null, STDOUT_FILENO), ::dup2(null, STDERR_FILENO);
          std::string said;
          try {
            const SubjectBinding subject = SubjectBinding::open(path);
            said = "ok " + std::to_string(subject.version());
            for (const std::string& kind : subject.kinds()) said += " " + kind;
          } catch (const std::exception& e) {
            said = std::string("no ") + e.what();
          }
          return write_all(out, said) ? 0 : 1;
        },
        load_seconds);
  } catch (const std::system_error& e) {
    throw SubjectLoadError(path + ": cannot be tried in a child process: " + e.what());
  }
  const std::string& said = probe.output;
  if (probe.succeeded() && said.starts_with("no ")) throw SubjectLoadError(said.substr(3));
  if (!probe.succeeded() || !said.starts_with("ok ")) {
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", load_seconds);
    const std::string what = probe.timed_out ? std::string("hung (still running after ") + limit + " s)" : probe.what();
    throw SubjectLoadError(path + ": " + what +
                           " while being loaded (in its constructors or crosscheck_subject_version), in a child process");
  }
  SubjectIdentity identity;
  std::istringstream words(said.substr(3));
  words >> identity.version;
  for (std::string kind; words >> kind;) identity.kinds.push_back(kind);
  identity.file = std::filesystem::path(path).filename().string();
  try {
    identity.sha256 = sha256_of_file(path);
  } catch (const std::runtime_error& e) {
    throw SubjectLoadError(e.what());
  }
  return std::make_shared<IsolatedSubject>(path, std::move(identity), call_seconds);
}

void set_call_seconds(Subject& subject, double call_seconds) {
  if (auto* isolated = dynamic_cast<IsolatedSubject*>(&subject)) isolated->set_call_seconds(call_seconds);
}

void ask_subject_afresh() {
  if (const auto* isolated = dynamic_cast<const IsolatedSubject*>(subject_under_test())) isolated->end_server_of_this_process();
}

std::optional<std::string> take_subject_output() {
  const auto* isolated = dynamic_cast<const IsolatedSubject*>(subject_under_test());
  return isolated != nullptr ? isolated->take_printed() : std::nullopt;
}

}  // namespace cc::harness
