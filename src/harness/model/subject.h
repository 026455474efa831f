// A subject: a shared library put under test in place of crosscheck's own, through the plain C
// interface of include/crosscheck/subject.h. This is the harness's handle on one; what calls
// it (in a child process, processes/subject_process.h) and what opens it there
// (subject_binding.h) live elsewhere.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/model/answer.h"
#include "harness/model/input.h"

namespace cc::harness {

/// Which subject answered: what a case found with one records, so that it is never replayed
/// against another library by mistake.
struct SubjectIdentity {
  std::string file;                // the file's name (no folder)
  int version = 0;                 // what its crosscheck_subject_version() returned
  std::string sha256;              // of the file's bytes, 64 hex digits
  std::vector<std::string> kinds;  // the query kinds it exports, in the registry's order
  friend bool operator==(const SubjectIdentity&, const SubjectIdentity&) = default;
};

/// The subject gave no answer to a query: it crashed, exited (with any status), hung, printed,
/// damaged a file descriptor it does not own, or returned something that is no answer. what()
/// says which, e.g. "exited with status 0" or "wrote to standard output: \"hello\"".
class SubjectFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Subject {
 public:
  virtual ~Subject() = default;
  /// The path it was loaded from, as given.
  virtual const std::string& path() const = 0;
  virtual const SubjectIdentity& identity() const = 0;
  /// It exports crosscheck_<kind>, for a kind whose input the interface expresses.
  bool answers(QueryKind kind) const;
  /// Its answer to the input: a hit or a miss, and for the mesh kinds the faces that meet (no
  /// ray parameter). Throws SubjectFailure when it gives none (see above), std::logic_error for
  /// a kind it does not answer.
  virtual Answer ask(const Input& input) const = 0;
};

/// The library under test: crosscheck's own (none set) or a subject, which ask_library then
/// asks (and the library's other ways to answer are not asked). Set it before the cases run:
/// worker processes inherit it.
void put_under_test(std::shared_ptr<const Subject> subject);
const Subject* subject_under_test();

/// Whether the library under test answers the kind (crosscheck's own answers every kind).
bool library_answers(QueryKind kind);

}  // namespace cc::harness
