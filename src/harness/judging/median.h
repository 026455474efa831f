// The median, as timings on a noisy machine are quoted.
#pragma once

#include <algorithm>
#include <vector>

namespace cc::harness {

/// The middle value (the mean of the two middle ones for an even count); 0 for none.
template <class T>
double median(std::vector<T> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? static_cast<double>(v[n / 2]) : 0.5 * (static_cast<double>(v[n / 2 - 1]) + static_cast<double>(v[n / 2]));
}

}  // namespace cc::harness
