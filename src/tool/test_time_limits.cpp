#include "tool/test_time_limits.h"

#include <algorithm>
#include <cstdio>

namespace cc::tool {

double TestTimeLimits::limit(const std::string& test) const {
  const auto it = own_seconds.find(test);
  if (it == own_seconds.end()) return std::max(unknown_seconds, floor_seconds);
  return std::max(factor * it->second, floor_seconds);
}

std::string TestTimeLimits::describe(const std::string& test) const {
  char text[160];
  const auto it = own_seconds.find(test);
  if (it == own_seconds.end()) {
    std::snprintf(text, sizeof text, "%.0f s (not timed on the unmutated tree)", limit(test));
  } else {
    std::snprintf(text, sizeof text, "%.0f s (%g times its %.2f s on the unmutated tree, at least %g s)", limit(test),
                  factor, it->second, floor_seconds);
  }
  return text;
}

}  // namespace cc::tool
