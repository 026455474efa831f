// Case files: one JSON text file per case. A case file holds the query
// kind, its inputs with exact round-trip numbers, the three parties' answers, the class and the
// margin, where the case came from, and a one-line note by whoever triaged it. Files are named
// by a hash of the query and its inputs, so a case is stored once and never overwritten.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/formats/input_json.h"
#include "harness/model/answer.h"
#include "harness/model/case_class.h"
#include "harness/model/oracle.h"
#include "harness/model/subject.h"

namespace cc::harness {

/// Version 2 stores only answers some party gave: a library that crashed or hung has "failed"
/// instead of an answer, an exact verdict not decided (or not computed) has no "hit", and a
/// campaign's case stored unshrunk says why. Version 1 files are still read.
inline constexpr int kCaseFormatVersion = 2;

/// Where a case came from: "campaign" (seed and case index), "property" (its name), "fuzz"
/// (the input bytes in hex), "shrink" (the file it was shrunk from) or "hand-written".
struct Provenance {
  std::string source = "hand-written";
  std::optional<std::uint64_t> seed;
  std::optional<std::uint64_t> case_index;
  std::string detail;  // property name, fuzz bytes, original file
};

struct Case {
  Input input;
  Answer library;
  std::string library_failure;  // what happened when the library crashed or hung; then `library` is no answer
  ExactVerdict exact;
  std::vector<Opinion> opinions;
  CaseClass cls = CaseClass::agree;
  Provenance provenance;
  std::string not_shrunk;  // why a campaign stored it as found (no time left, interrupted); empty: shrunk
  std::string note;
  std::optional<SubjectIdentity> subject;  // the subject whose answer `library` is; none: crosscheck's own
};

/// A problem with a case file: the file, the place in it ("line 3, column 14" or a JSON pointer
/// such as "/inputs/origin/1"), and what is wrong.
class CaseFileError : public std::runtime_error {
 public:
  CaseFileError(std::string file, std::string place, const std::string& message);
  const std::string& file() const { return file_; }
  const std::string& place() const { return place_; }

 private:
  std::string file_, place_;
};

Json case_to_json(const Case& c);
/// An answer as a case file stores it ({"hit", "params", "pairs", "frames"}, doubles exactly):
/// two answers are the same, bit for bit, when their JSON is.
Json answer_json(const Answer& a);
/// Reads one back; throws FormatError naming the place (`pointer`, the answer's JSON pointer).
Answer answer_from_json(const Json& j, const std::string& pointer);
/// The opinions as a case file stores them ("answers"/"oracles"), doubles exactly.
Json opinions_to_json(const std::vector<Opinion>& opinions);
/// Reads them back; throws FormatError naming the place (`place` is the array's JSON pointer).
std::vector<Opinion> opinions_from_json(const Json& opinions, const std::string& place);
/// Throws FormatError (with a JSON pointer) for a document that is not a valid case. Mesh files
/// are looked for from case_dir (see find_mesh_file).
Case case_from_json(const Json& json, const std::filesystem::path& case_dir = {});

/// Reads a case file; throws CaseFileError for a folder, an unreadable file, a syntax error, a
/// "format" other than "crosscheck-case", an unknown field, an unknown query kind, a missing
/// field, a number that does not parse, or a newer format version.
Case read_case_file(const std::filesystem::path& path);
/// The same for a case file's text: `file` names it in errors, mesh files are looked for from
/// `case_dir`.
Case read_case_text(const std::string& content, const std::string& file, const std::filesystem::path& case_dir);

/// The file name of a case: 16 hex digits of a 64-bit FNV-1a hash of its query and inputs.
std::string case_file_name(const Input& input);

/// Writes the case as a new file at `path` (its folders created), exclusively: a temporary file
/// in the same folder is link()ed to the name, which never replaces a file, and removed. If
/// `path` holds another case (another query or inputs), the next free name "<stem>-2.json",
/// "-3", ... is taken. Returns the path written, or nothing (writing nothing) when the file, or
/// one of those, holds this very query and inputs already. Throws CaseFileError, naming the file
/// and the reason, when it cannot be written.
std::optional<std::filesystem::path> write_new_case_file(const std::filesystem::path& path, const Case& c);

/// Writes the case over the file at `path`: into a temporary file beside it first, then renamed
/// over it, so that a failed write leaves the old file as it was. Throws CaseFileError, naming
/// the file and the reason.
void replace_case_file(const std::filesystem::path& path, const Case& c);

/// Every case file (*.json) under the directories given, recursively, sorted.
std::vector<std::filesystem::path> case_files_under(const std::vector<std::filesystem::path>& roots);

}  // namespace cc::harness
