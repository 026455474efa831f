// A subject (include/crosscheck/subject.h) opened and called only in child processes: whatever
// its code does (crash, exit with any status, hang, print, close or write to descriptors it does
// not own) is its failure in that case, never the end or the damage of the caller.
//
// Loading is tried first in a child of its own (load_subject). Then each process that asks the
// subject (the tool, a campaign's worker, a shrinking child) starts, at its first question, a
// server: a fork of itself that opens the subject and answers questions over two pipes, with
// standard input /dev/null, standard output and error in files of its own, and every other
// descriptor closed. A question goes over as the input's JSON (exactly, as case files store it)
// and the answer comes back the same way. After each call the server checks its descriptors and
// its output files; the client checks the answer's framing and the time limit. A server that
// fails is ended (SIGKILL) and the next question starts another.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "harness/model/subject.h"

namespace cc::harness {

/// Seconds a subject may take to load (its constructors and crosscheck_subject_version) in the
/// child that tries it.
inline constexpr double kSubjectLoadSeconds = 10;

/// A subject's load failed (it is no subject, or its loading crashed, exited or hung). what() is
/// one line naming the file and what happened.
class SubjectLoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Tries the subject at `path` in a child process (a bare name is looked up in the current
/// folder): it must load, return CROSSCHECK_SUBJECT_VERSION and export some crosscheck_<kind>,
/// within `load_seconds`, and the child must come back. Returns a handle whose ask() runs the
/// subject in a server process (above), each call limited to `call_seconds` (> 0), and whose
/// identity() names the file, its version, its SHA-256 and its kinds. Throws SubjectLoadError.
std::shared_ptr<Subject> load_subject(const std::string& path, double call_seconds,
                                      double load_seconds = kSubjectLoadSeconds);

/// Ends the server this process runs for the subject under test, if it has one, so that the
/// next question starts another: a process with no history, as a fresh command's. Nothing for a
/// subject that load_subject did not load.
void ask_subject_afresh();

/// The first line the subject under test printed (on standard output or error, "standard
/// output: <line>") in this process's calls since the last take; nothing if it printed none.
/// Printing is also each such call's failure.
std::optional<std::string> take_subject_output();

/// Sets how long one call of a subject loaded by load_subject may take from now on (> 0).
void set_call_seconds(Subject& subject, double call_seconds);

}  // namespace cc::harness
