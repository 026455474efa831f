#include "harness/judging/evaluate.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <string>

#include "harness/formats/case_file.h"
#include "harness/model/library.h"

namespace cc::harness {

Evaluation evaluate(const Input& input, const ExactReference& exact, const SecondOpinion* second) {
  Evaluation e;
  e.library = ask_library(input);
  e.exact = exact.judge(input);
  e.opinions = library_alternatives(input);
  if (second != nullptr) {
    for (Opinion& o : second->opinions(input)) e.opinions.push_back(std::move(o));
  }
  e.verdict = classify(kind_of(input), e.library, e.exact, e.opinions);
  return e;
}

void restore_bands(std::vector<Opinion>& opinions, const SecondOpinion& second, QueryKind kind) {
  const std::vector<PartyBand> declared = second.parties(kind);
  for (Opinion& o : opinions) {
    for (const PartyBand& p : declared) {
      if (p.party == o.party) o.band = p.band;
    }
  }
}

std::optional<Evaluation> evaluate_in_child(const Input& input, const ExactReference& exact, const SecondOpinion& second) {
  int fds[2];
  if (pipe(fds) != 0) return std::nullopt;
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t pid = fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    return std::nullopt;
  }
  if (pid == 0) {
    ::close(fds[0]);
    const std::string text = opinions_to_json(evaluate(input, exact, &second).opinions).dump();
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fds[1], text.data() + done, text.size() - done);
      if (n <= 0 && errno != EINTR) std::_Exit(1);
      if (n > 0) done += static_cast<std::size_t>(n);
    }
    std::_Exit(0);
  }
  ::close(fds[1]);
  std::string text;
  char chunk[65536];
  for (ssize_t n; (n = ::read(fds[0], chunk, sizeof chunk)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(chunk, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  Evaluation e;
  try {
    e.opinions = opinions_from_json(Json::parse(text), "");
    restore_bands(e.opinions, second, kind_of(input));
  } catch (const std::exception&) {
    return std::nullopt;
  }
  e.library = ask_library(input);
  e.exact = exact.judge(input);
  e.verdict = classify(kind_of(input), e.library, e.exact, e.opinions);
  return e;
}

}  // namespace cc::harness
