// The mutant catalogue: small patches of the library, each an exact text search and replace, so
// that a mutant survives unrelated edits of its file and a stale one is found, never skipped.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cc::tool {

/// One mutant: in `file` (relative to the source root) the text `original`, which must occur
/// exactly once, becomes `replacement`.
struct Mutant {
  std::string id;           // unique, e.g. "sphere.strict_compare"
  std::string query;        // the query kind whose campaign aims at it, a name from the registry
  std::string file;         // e.g. "src/collide/sphere.cpp"
  std::string original;     // exact text, occurring once in the file
  std::string replacement;  // what it becomes
  std::string description;  // one line: the bug a real engineer could have written
  std::string equivalent;   // non-empty: why it cannot change any answer (left out of the score)
  /// Non-empty: the SIMD kernel (simd::to_string) the mutated code belongs to; it runs only on
  /// processors that support that kernel, and elsewhere the mutant is not executable.
  std::string kernel;
};

/// A bad catalogue: the message names the file and the place (line and column, or a JSON
/// pointer such as /mutants/3/original).
struct CatalogueError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads and checks a catalogue file ({"format": "crosscheck-mutants", "version": 1,
/// "mutants": [...]}): every field present and a string, ids unique, original != replacement,
/// a kernel (optional) one of simd::kAllKernels. Throws CatalogueError.
std::vector<Mutant> read_catalogue(const std::filesystem::path& path);

/// Whether a mutant applies to a file's text: nullopt when `original` occurs exactly once,
/// otherwise why it is stale ("not found", or "occurs 3 times").
std::optional<std::string> staleness(const Mutant& m, const std::string& text);

/// Why this processor cannot run the mutant's code (its kernel is one it lacks), or nothing.
std::optional<std::string> not_executable_here(const Mutant& m);

/// The file's text with the mutant applied (the caller has checked staleness).
std::string mutated(const Mutant& m, const std::string& text);

/// A file's whole content; throws std::runtime_error naming the file when it cannot be read.
std::string read_text(const std::filesystem::path& path);

/// Writes a file's whole content; throws std::runtime_error naming the file on failure.
void write_text(const std::filesystem::path& path, const std::string& text);

}  // namespace cc::tool
