// --subject PATH: put a shared library (include/crosscheck/subject.h) under test in place of
// crosscheck's own library, for the commands that judge answers.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "harness/model/query_kind.h"

namespace cc::tool {

/// Adds --subject to the command. The flag is checked before any work starts: the library is
/// loaded then, and a path that is no subject ends the run with exit status 2 and the reason.
void add_subject_option(CLI::App* cmd, std::string& path);

/// Puts the subject at `path` under test (nothing for an empty path).
void put_subject_under_test(const std::string& path);

/// Of `kinds`, those the library under test answers (all of them without a subject); prints the
/// others, skipped, on standard output, prefixed by the command's name.
std::vector<harness::QueryKind> answered_kinds(const std::vector<harness::QueryKind>& kinds, const char* command);

}  // namespace cc::tool
