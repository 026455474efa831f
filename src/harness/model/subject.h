// A subject: a shared library put under test in place of crosscheck's own, through the plain C
// interface of include/crosscheck/subject.h (crosscheck_<kind> functions on structs of doubles).
#pragma once

#include <array>
#include <memory>
#include <string>

#include "harness/model/answer.h"
#include "harness/model/input.h"

namespace cc::harness {

class Subject {
 public:
  /// Loads the shared library at `path` (a path, as given: a bare name is looked up in the
  /// current folder, not the loader's). Throws std::runtime_error with a sentence naming the
  /// path and the problem: it cannot be loaded (the loader's message), it exports no
  /// crosscheck_subject_version, its version is not CROSSCHECK_SUBJECT_VERSION, or it answers
  /// no query kind.
  static std::shared_ptr<const Subject> load(const std::string& path);

  const std::string& path() const { return path_; }
  /// It exports crosscheck_<kind>, for a kind whose input the interface expresses.
  bool answers(QueryKind kind) const { return functions_[static_cast<std::size_t>(kind)] != nullptr; }
  /// Its answer to the input: a hit or a miss, and for the mesh kinds the faces that meet (no
  /// ray parameter). Throws std::runtime_error when it does not answer the kind, returns neither
  /// 0 nor 1, or names a face the meshes do not have.
  Answer ask(const Input& input) const;

 private:
  std::string path_;
  std::array<void*, kAllQueryKinds.size()> functions_{};
};

/// The library under test: crosscheck's own (none set) or a subject, which ask_library then
/// asks (and the library's other ways to answer are not asked). Set it before the cases run:
/// worker processes inherit it.
void put_under_test(std::shared_ptr<const Subject> subject);
const Subject* subject_under_test();

/// Whether the library under test answers the kind (crosscheck's own answers every kind).
bool library_answers(QueryKind kind);

}  // namespace cc::harness
