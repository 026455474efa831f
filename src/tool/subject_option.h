// --subject PATH: put a shared library (include/crosscheck/subject.h) under test in place of
// crosscheck's own library, for the commands that judge answers. Without the flag, the
// environment variable CROSSCHECK_SUBJECT gives it.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "harness/formats/case_file.h"
#include "harness/model/query_kind.h"

namespace cc::tool {

/// The environment variable that names the subject when --subject is not given.
inline constexpr const char* kSubjectVariable = "CROSSCHECK_SUBJECT";

/// Adds --subject to the command. The flag is checked before any work starts: the library is
/// tried in a child process then (harness::load_subject), and a path that is no subject, or
/// whose loading crashes, exits or hangs, ends the run with exit status 2 and one line naming
/// the file and what happened.
void add_subject_option(CLI::App* cmd, std::string& path);

/// Puts the subject at `path` under test (nothing for an empty path), each of its calls limited
/// to `call_seconds`.
void put_subject_under_test(const std::string& path, double call_seconds);

/// Whether the case may be answered now: a case found with a subject is answered by a subject
/// only, never by crosscheck's own library in its place. False (with a line on stderr naming
/// the file, the subject it records and how to give one) for such a case with no subject under
/// test; true otherwise, with a note on stderr when the subject under test is not the file the
/// case records (another build of it: its answers are what the command shows).
bool subject_fits_case(const harness::Case& c, const std::string& file, const char* command);

/// Of `kinds`, those the library under test answers (all of them without a subject); prints the
/// others, skipped, on standard output, prefixed by the command's name.
std::vector<harness::QueryKind> answered_kinds(const std::vector<harness::QueryKind>& kinds, const char* command);

}  // namespace cc::tool
