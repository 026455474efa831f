// How long a test may run in a mutant's tree before it counts as failed (a hang the mutant
// caused): five times its own time on the unmutated tree, never below a floor (the machine may
// be shared, and a loaded machine must not make a mutant look caught).
#pragma once

#include <map>
#include <string>

namespace cc::tool {

struct TestTimeLimits {
  double factor = 5;
  double floor_seconds = 10;
  /// Seconds each test took on the unmutated tree.
  std::map<std::string, double> own_seconds;
  /// For a test the unmutated tree did not time (no baseline, or a test not in it).
  double unknown_seconds = 600;

  /// The limit of a test: max(factor * its own time, floor), or unknown_seconds.
  double limit(const std::string& test) const;
  /// The limit in words, for a report: "5 times its 0.4 s on the unmutated tree, at least 10 s".
  std::string describe(const std::string& test) const;
};

}  // namespace cc::tool
