#include "harness/formats/case_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "harness/formats/input_file.h"
#include "harness/formats/json_text.h"
#include "harness/formats/number_text.h"
#include "harness/formats/write_all.h"

namespace cc::harness {
namespace {

std::string_view contract_name(Contract c) {
  switch (c) {
    case Contract::in: return "in";
    case Contract::documented: return "documented";
    case Contract::unspecified: return "unspecified";
  }
  return "?";
}

std::string_view status_name(Opinion::Status s) {
  switch (s) {
    case Opinion::Status::answered: return "answered";
    case Opinion::Status::not_applicable: return "n/a";
    case Opinion::Status::failed: return "failed";
    case Opinion::Status::timed_out: return "timed out";
  }
  return "?";
}

Json numbers(const std::vector<double>& xs) {
  Json a = Json::array();
  for (double x : xs) a.push_back(number_to_json(x));
  return a;
}

// Reading helpers that name the place of every problem.
const Json& member(const Json& j, const std::string& pointer, const std::string& name) {
  if (!j.is_object()) throw FormatError(pointer, "expected an object");
  const auto it = j.find(name);
  if (it == j.end()) throw FormatError(pointer, "missing field \"" + name + "\"");
  return *it;
}
std::string text(const Json& j, const std::string& pointer) {
  if (!j.is_string()) throw FormatError(pointer, "expected a string");
  return j.get<std::string>();
}
bool boolean(const Json& j, const std::string& pointer) {
  if (!j.is_boolean()) throw FormatError(pointer, "expected true or false");
  return j.get<bool>();
}
std::vector<double> numbers_from(const Json& j, const std::string& pointer) {
  if (!j.is_array()) throw FormatError(pointer, "expected an array of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < j.size(); ++i) out.push_back(number_from_json(j[i], pointer + "/" + std::to_string(i)));
  return out;
}
std::uint64_t unsigned_from(const Json& j, const std::string& pointer) {
  if (!j.is_number_unsigned()) throw FormatError(pointer, "expected a non-negative integer");
  return j.get<std::uint64_t>();
}
std::vector<FacePair> pairs_from(const Json& j, const std::string& pointer) {
  if (!j.is_array()) throw FormatError(pointer, "expected an array of [face of a, face of b] pairs");
  std::vector<FacePair> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = pointer + "/" + std::to_string(i);
    if (!j[i].is_array() || j[i].size() != 2 || !j[i][0].is_number_unsigned() || !j[i][1].is_number_unsigned()) {
      throw FormatError(p, "expected [face of a, face of b]");
    }
    out.emplace_back(j[i][0].get<std::uint32_t>(), j[i][1].get<std::uint32_t>());
  }
  return out;
}
// Refuses a member of `j` not named in `known`: a misspelt or foreign field is an error, not
// silently ignored.
void only_fields(const Json& j, const std::string& pointer, std::initializer_list<std::string_view> known) {
  if (!j.is_object()) throw FormatError(pointer, "expected an object");
  for (const auto& [key, value] : j.items()) {
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      throw FormatError(pointer + "/" + key, "unknown field \"" + key + "\"");
    }
  }
}
// The first member of `given` (its JSON pointer) that `written`, the same value as the writer
// writes it, does not have; "" when there is none. Arrays are compared element by element.
std::string unknown_member(const Json& given, const Json& written, const std::string& pointer) {
  if (given.is_object() && written.is_object()) {
    for (const auto& [key, value] : given.items()) {
      if (!written.contains(key)) return pointer + "/" + key;
      if (std::string p = unknown_member(value, written[key], pointer + "/" + key); !p.empty()) return p;
    }
  } else if (given.is_array() && written.is_array() && given.size() == written.size()) {
    for (std::size_t i = 0; i < given.size(); ++i) {
      if (std::string p = unknown_member(given[i], written[i], pointer + "/" + std::to_string(i)); !p.empty()) return p;
    }
  }
  return "";
}

// hit, and the parameters or pairs when there are any.
void read_answer(const Json& j, const std::string& pointer, Answer& a) {
  a.hit = boolean(member(j, pointer, "hit"), pointer + "/hit");
  if (j.contains("params")) a.params = numbers_from(j["params"], pointer + "/params");
  if (j.contains("pairs")) a.pairs = pairs_from(j["pairs"], pointer + "/pairs");
  if (j.contains("frames")) {
    const Json& frames = j["frames"];
    if (!frames.is_array()) throw FormatError(pointer + "/frames", "expected an array of frames, each a list of pairs");
    for (std::size_t f = 0; f < frames.size(); ++f) {
      a.frames.push_back(pairs_from(frames[f], pointer + "/frames/" + std::to_string(f)));
    }
  }
}
Answer answer_from(const Json& j, const std::string& pointer) {
  only_fields(j, pointer, {"hit", "params", "pairs", "frames"});
  Answer a;
  read_answer(j, pointer, a);
  return a;
}
void write_answer(const Answer& a, Json& j) {
  j["hit"] = a.hit;
  if (!a.params.empty()) j["params"] = numbers(a.params);
  if (!a.pairs.empty()) {
    Json pairs = Json::array();
    for (const auto& [i, k] : a.pairs) pairs.push_back(Json::array({i, k}));
    j["pairs"] = pairs;
  }
  if (!a.frames.empty()) {
    Json frames = Json::array();
    for (const auto& frame : a.frames) {
      Json pairs = Json::array();
      for (const auto& [i, k] : frame) pairs.push_back(Json::array({i, k}));
      frames.push_back(pairs);
    }
    j["frames"] = frames;
  }
}

std::uint64_t fnv1a(std::string_view s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

// "line L, column C" of a byte offset in a text.

}  // namespace

CaseFileError::CaseFileError(std::string file, std::string place, const std::string& message)
    : std::runtime_error(file + ": " + (place.empty() ? "" : place + ": ") + message),
      file_(std::move(file)),
      place_(std::move(place)) {}

Answer answer_from_json(const Json& j, const std::string& pointer) { return answer_from(j, pointer); }

Json answer_json(const Answer& a) {
  Json j = Json::object();
  write_answer(a, j);
  return j;
}

Json opinions_to_json(const std::vector<Opinion>& opinions) {
  Json out = Json::array();
  for (const Opinion& o : opinions) {
    Json j = {{"party", o.party}, {"status", status_name(o.status)}};
    if (o.status == Opinion::Status::answered) write_answer(o.answer, j);
    if (!o.detail.empty()) j["detail"] = o.detail;
    out.push_back(j);
  }
  return out;
}

std::vector<Opinion> opinions_from_json(const Json& opinions, const std::string& place) {
  if (!opinions.is_array()) throw FormatError(place, "expected an array");
  std::vector<Opinion> out;
  for (std::size_t i = 0; i < opinions.size(); ++i) {
    const std::string p = place + "/" + std::to_string(i);
    Opinion o;
    only_fields(opinions[i], p, {"party", "status", "detail", "hit", "params", "pairs", "frames"});
    o.party = text(member(opinions[i], p, "party"), p + "/party");
    const std::string status = text(member(opinions[i], p, "status"), p + "/status");
    if (status == "answered") {
      o.status = Opinion::Status::answered;
      read_answer(opinions[i], p, o.answer);
    } else if (status == "n/a") {
      o.status = Opinion::Status::not_applicable;
    } else if (status == "failed") {
      o.status = Opinion::Status::failed;
    } else if (status == "timed out") {
      o.status = Opinion::Status::timed_out;
    } else {
      throw FormatError(p + "/status", "expected \"answered\", \"n/a\", \"failed\" or \"timed out\"");
    }
    o.detail = opinions[i].contains("detail") ? text(opinions[i]["detail"], p + "/detail") : "";
    out.push_back(o);
  }
  return out;
}

Json case_to_json(const Case& c) {
  const Json opinions = opinions_to_json(c.opinions);
  Json exact = c.exact.decided ? answer_json(c.exact.answer) : Json::object();  // an answer only when one was given
  exact["contract"] = contract_name(c.exact.contract);
  exact["decided"] = c.exact.decided;
  if (!c.exact.note.empty()) exact["note"] = c.exact.note;
  Json provenance = {{"source", c.provenance.source}};
  if (c.provenance.seed) provenance["seed"] = *c.provenance.seed;
  if (c.provenance.case_index) provenance["case"] = *c.provenance.case_index;
  if (!c.provenance.detail.empty()) provenance["detail"] = c.provenance.detail;
  if (!c.not_shrunk.empty()) provenance["not_shrunk"] = c.not_shrunk;
  const Json library = c.library_failure.empty() ? answer_json(c.library) : Json{{"failed", c.library_failure}};
  Json j = {{"format", "crosscheck-case"},
          {"version", kCaseFormatVersion},
          {"query", name(kind_of(c.input))},
          {"note", c.note},
          {"class", to_string(c.cls)},
          {"margin", number_to_json(c.exact.margin)},
          {"inputs", input_to_json(c.input)},
          {"answers", {{"library", library}, {"exact", exact}, {"oracles", opinions}}},
          {"provenance", provenance}};
  if (c.subject) {
    j["subject"] = {{"file", c.subject->file},
                    {"version", c.subject->version},
                    {"sha256", c.subject->sha256},
                    {"kinds", c.subject->kinds}};
  }
  return j;
}

Case case_from_json(const Json& json, const std::filesystem::path& case_dir) {
  if (!json.is_object()) throw FormatError("", "expected a JSON object");
  const Json& format_name = member(json, "", "format");
  if (format_name != "crosscheck-case") {
    throw FormatError("/format", "expected \"crosscheck-case\", not " + format_name.dump());
  }
  only_fields(json, "", {"format", "version", "query", "note", "class", "margin", "inputs", "answers", "provenance", "subject"});
  const auto version = member(json, "", "version");
  if (!version.is_number_integer()) throw FormatError("/version", "expected an integer");
  if (version.get<int>() > kCaseFormatVersion || version.get<int>() < 1) {
    throw FormatError("/version", "format version " + std::to_string(version.get<int>()) +
                                      " is not supported (this build reads versions 1 to " +
                                      std::to_string(kCaseFormatVersion) + ")");
  }
  const std::string query = text(member(json, "", "query"), "/query");
  const auto kind = query_kind_named(query);
  if (!kind) throw FormatError("/query", "unknown query kind \"" + query + "\"");

  Case c;
  c.input = input_from_json(*kind, member(json, "", "inputs"), "/inputs", case_dir);
  if (const std::string p = unknown_member(json["inputs"], input_to_json(c.input), "/inputs"); !p.empty()) {
    throw FormatError(p, "unknown field \"" + p.substr(p.rfind('/') + 1) + "\" of a " + query + " input");
  }
  c.note = json.contains("note") ? text(json["note"], "/note") : "";
  const std::string cls = text(member(json, "", "class"), "/class");
  const auto parsed = case_class_named(cls);
  if (!parsed) throw FormatError("/class", "unknown class \"" + cls + "\"");
  c.cls = *parsed;

  const int format = version.get<int>();
  const Json& answers = member(json, "", "answers");
  only_fields(answers, "/answers", {"library", "exact", "oracles"});
  const Json& library = member(answers, "/answers", "library");
  if (format >= 2 && library.is_object() && library.contains("failed")) {
    only_fields(library, "/answers/library", {"failed"});
    c.library_failure = text(library["failed"], "/answers/library/failed");
  } else {
    c.library = answer_from(library, "/answers/library");
  }
  const Json& exact = member(answers, "/answers", "exact");
  only_fields(exact, "/answers/exact", {"hit", "params", "pairs", "frames", "contract", "decided", "note"});
  c.exact.margin = number_from_json(member(json, "", "margin"), "/margin");
  const std::string contract = text(member(exact, "/answers/exact", "contract"), "/answers/exact/contract");
  if (contract == "in") {
    c.exact.contract = Contract::in;
  } else if (contract == "documented") {
    c.exact.contract = Contract::documented;
  } else if (contract == "unspecified") {
    c.exact.contract = Contract::unspecified;
  } else {
    throw FormatError("/answers/exact/contract", "expected \"in\", \"documented\" or \"unspecified\"");
  }
  c.exact.decided = exact.contains("decided") ? boolean(exact["decided"], "/answers/exact/decided") : true;
  // Version 1 wrote a default answer for a verdict nobody gave (out of contract, unspecified).
  if (format == 1 && c.exact.contract == Contract::unspecified) c.exact.decided = false;
  if (c.exact.decided || exact.contains("hit")) read_answer(exact, "/answers/exact", c.exact.answer);
  c.exact.note = exact.contains("note") ? text(exact["note"], "/answers/exact/note") : "";
  c.opinions = opinions_from_json(member(answers, "/answers", "oracles"), "/answers/oracles");
  if (json.contains("provenance")) {
    const Json& p = json["provenance"];
    only_fields(p, "/provenance", {"source", "seed", "case", "detail", "not_shrunk"});
    c.provenance.source = text(member(p, "/provenance", "source"), "/provenance/source");
    if (p.contains("seed")) c.provenance.seed = unsigned_from(p["seed"], "/provenance/seed");
    if (p.contains("case")) c.provenance.case_index = unsigned_from(p["case"], "/provenance/case");
    if (p.contains("detail")) c.provenance.detail = text(p["detail"], "/provenance/detail");
    if (p.contains("not_shrunk")) c.not_shrunk = text(p["not_shrunk"], "/provenance/not_shrunk");
  }
  if (json.contains("subject")) {
    const Json& s = json["subject"];
    only_fields(s, "/subject", {"file", "version", "sha256", "kinds"});
    SubjectIdentity subject;
    subject.file = text(member(s, "/subject", "file"), "/subject/file");
    const Json& subject_version = member(s, "/subject", "version");
    if (!subject_version.is_number_integer() || subject_version.get<std::int64_t>() != subject_version.get<int>()) {
      throw FormatError("/subject/version", "expected an integer");
    }
    subject.version = subject_version.get<int>();
    subject.sha256 = text(member(s, "/subject", "sha256"), "/subject/sha256");
    const Json& kinds = member(s, "/subject", "kinds");
    if (!kinds.is_array()) throw FormatError("/subject/kinds", "expected an array of query kinds");
    for (std::size_t i = 0; i < kinds.size(); ++i) subject.kinds.push_back(text(kinds[i], "/subject/kinds/" + std::to_string(i)));
    c.subject = std::move(subject);
  }
  return c;
}

Case read_case_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::string text;
  try {
    text = read_input_file(path, kMaxCaseFileBytes, "case file");
  } catch (const InputFileError& e) {
    throw CaseFileError(file, "", e.what());
  }
  return read_case_text(text, file, path.parent_path());
}

Case read_case_text(const std::string& content, const std::string& file, const std::filesystem::path& case_dir) {
  Json json;
  try {
    json = parse_json_text(content);
  } catch (const JsonTextError& e) {
    throw CaseFileError(file, e.place(), e.what());
  }
  try {
    return case_from_json(json, case_dir);
  } catch (const FormatError& e) {
    throw CaseFileError(file, e.pointer().empty() ? "/" : e.pointer(), e.what());
  }
}

std::string case_file_name(const Input& input) {
  const Json key = {{"query", name(kind_of(input))}, {"inputs", input_to_json(input)}};
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(key.dump())));
  return std::string(hex) + ".json";
}

namespace {

CaseFileError file_failure(const std::filesystem::path& where, const std::string& what, int error) {
  return CaseFileError(where.string(), "", what + ": " + std::strerror(error));
}

// The case written whole into a new temporary file beside `path` (its folders made), not named
// *.json, so that a reader of the folder never takes it for a case. Returns its path.
std::string write_temporary_case_file(const std::filesystem::path& path, const Case& c) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw CaseFileError(path.string(), "", "cannot create the folder " + dir.string() + ": " + ec.message());
  std::string temp = (dir / ('.' + path.filename().string() + ".tmp-XXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw file_failure(dir, "cannot create a file in the folder", errno);
  // A text from elsewhere (a subject's message, a note) may hold bytes that are not UTF-8.
  const std::string text = case_to_json(c).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
  const bool written = write_all(fd, text) && ::fchmod(fd, 0644) == 0 && ::fsync(fd) == 0;
  const int write_error = errno;
  if (::close(fd) != 0 || !written) {
    ::unlink(temp.c_str());
    throw file_failure(temp, "cannot write the file", write_error);
  }
  return temp;
}

}  // namespace

void replace_case_file(const std::filesystem::path& path, const Case& c) {
  const std::string temp = write_temporary_case_file(path, c);
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temp.c_str());
    throw file_failure(path, "cannot replace the file", error);
  }
}

std::optional<std::filesystem::path> write_new_case_file(const std::filesystem::path& path, const Case& c) {
  const std::string temp = write_temporary_case_file(path, c);
  const std::string stem = path.stem().string(), extension = path.extension().string();
  const std::string key = Json{{"query", name(kind_of(c.input))}, {"inputs", input_to_json(c.input)}}.dump();
  for (int n = 1;; ++n) {
    std::filesystem::path target = path;
    if (n > 1) target.replace_filename(stem + '-' + std::to_string(n) + extension);
    if (::link(temp.c_str(), target.c_str()) == 0) {
      ::unlink(temp.c_str());
      return target;
    }
    const int error = errno;
    if (error != EEXIST) {
      ::unlink(temp.c_str());
      throw file_failure(target, "cannot create the file", error);
    }
    // Taken: by this very case (nothing to write), or by another whose name is the same hash.
    try {
      const Case there = read_case_file(target);
      if (Json{{"query", name(kind_of(there.input))}, {"inputs", input_to_json(there.input)}}.dump() == key) {
        ::unlink(temp.c_str());
        return std::nullopt;
      }
    } catch (const CaseFileError&) {  // unreadable or another format: not this case; keep it
    }
  }
}

std::vector<std::filesystem::path> case_files_under(const std::vector<std::filesystem::path>& roots) {
  std::vector<std::filesystem::path> files;
  for (const auto& root : roots) {
    if (std::filesystem::is_regular_file(root)) {
      files.push_back(root);
      continue;
    }
    if (!std::filesystem::is_directory(root)) continue;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace cc::harness
