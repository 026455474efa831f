// Running a program as a user runs it, for the command-line tests: its exit status (128 + the
// signal's number when one ended it), and its output and error kept apart.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "harness/processes/child.h"

namespace cc::test {

/// A file's whole text ("" when it cannot be read).
inline std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Outcome {
  int status = -1;
  std::string out, err;
};

/// Runs argv in the folder `cwd`, its output and error through files in `scratch` (stdout,
/// stderr, replaced), within 120 s.
inline Outcome run(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                   const std::filesystem::path& scratch) {
  const std::filesystem::path out = scratch / "stdout", err = scratch / "stderr";
  std::filesystem::remove(out), std::filesystem::remove(err);
  const harness::ChildEnd end = harness::run_program(argv, {cwd, out, err}, 120);
  return {end.signal != 0 ? 128 + end.signal : end.status, text_of(out), text_of(err)};
}

}  // namespace cc::test
