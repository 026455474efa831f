// Reading ctest's output (one test at a time, -j1): the time each test took, the tests that
// failed, and, while ctest runs, the test running now.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cc::tool {

/// Per test that passed, the seconds ctest reports ("  3/9 Test  #12: name ....   Passed    0.40 sec").
std::map<std::string, double> passed_test_seconds(const std::string& log);

/// The tests that failed ("Test  #12: name ....***Failed", "...***Timeout"; not "***Skipped"),
/// in order: their names and how they failed.
std::vector<std::pair<std::string, std::string>> failed_tests(const std::string& log);

/// Follows a ctest log as it grows: the test started last and not finished yet, if any.
class RunningTest {
 public:
  /// Reads more of the log (any split into pieces; a line is read once it is whole).
  void feed(std::string_view more);
  /// The test running now: started ("    Start 12: name") and not yet reported.
  const std::optional<std::string>& name() const { return running_; }

 private:
  std::string partial_;
  std::optional<std::string> running_;
};

}  // namespace cc::tool
