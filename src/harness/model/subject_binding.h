// A subject opened in this very process: dlopen, its version checked, its crosscheck_<kind>
// functions found and called on the C structs of include/crosscheck/subject.h. Whatever the
// subject's code does happens to the process that opened it, so only a child process opens one
// (processes/subject_process.h): the harness never calls this directly.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "harness/model/answer.h"
#include "harness/model/input.h"

namespace cc::harness {

class SubjectBinding {
 public:
  /// Opens the shared library at `path` (a path, as given: a bare name is looked up in the
  /// current folder, not the loader's), running its constructors, and calls its
  /// crosscheck_subject_version(). Throws std::runtime_error with a sentence naming the path and
  /// the problem: it cannot be loaded (the loader's message), it exports no
  /// crosscheck_subject_version, its version is not CROSSCHECK_SUBJECT_VERSION, or it answers no
  /// query kind, or it answers a distance kind without a crosscheck_distance_tolerance() in
  /// [0, 1). The library stays loaded for the process's life.
  static SubjectBinding open(const std::string& path);

  int version() const { return version_; }
  /// It exports crosscheck_<kind>, for a kind whose input the interface expresses.
  bool answers(QueryKind kind) const { return functions_[static_cast<std::size_t>(kind)] != nullptr; }
  /// The names of the kinds it answers, in the registry's order.
  std::vector<std::string> kinds() const;
  /// Its answer to the input: a hit or a miss, and for the mesh kinds the faces that meet (no
  /// ray parameter); for a distance kind the distance, the two points and, as the bounds a
  /// distance answer certifies (Judged::distance), its tolerance times the shapes' largest
  /// magnitude, twice. Throws std::runtime_error when it does not answer the kind, returns
  /// neither 0 nor 1 (a distance: not 1), or names a face the meshes do not have.
  Answer ask(const Input& input) const;

 private:
  std::string path_;
  int version_ = 0;
  double distance_tolerance_ = 0;
  std::array<void*, kAllQueryKinds.size()> functions_{};
};

}  // namespace cc::harness
