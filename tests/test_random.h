// Random numbers for tests, from the raw 64-bit outputs of one engine (std's distributions
// differ between standard libraries, so a seed gives the same cases everywhere).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "collide/vec3.h"

namespace cc::test {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  /// A double in [0, 1), a multiple of 2^-53.
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  double between(double lo, double hi) { return lo + (hi - lo) * unit(); }
  /// An integer in [0, n).
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
  /// An integer in [lo, hi].
  int in(int lo, int hi) { return lo + below(hi - lo + 1); }
  /// An integer in [-2^bits, 2^bits] (bits <= 62).
  std::int64_t integer(int bits) {
    const std::uint64_t span = (std::uint64_t{1} << (bits + 1)) + 1;
    return static_cast<std::int64_t>(engine_() % span) - (std::int64_t{1} << bits);
  }
  Vec3 in_cube(double h) { return {between(-h, h), between(-h, h), between(-h, h)}; }
  /// A scale for a drawn case: 1, a power of two from 2^-300 to 2^300, one of those two ends, or
  /// anything in [1e-3, 1e3].
  double scale() {
    switch (below(4)) {
      case 0: return 1;
      case 1: return std::ldexp(1.0, in(-300, 300));
      case 2: return std::ldexp(1.0, below(2) ? -300 : 300);
      default: return between(1e-3, 1e3);
    }
  }
  /// A point with integer coordinates in [-h, h].
  Vec3 integer_point(int h) { return {double(in(-h, h)), double(in(-h, h)), double(in(-h, h))}; }
  /// x moved by 0, 1 or 2 ulps up or down.
  double perturbed(double x) {
    const int steps = below(3);
    const double to = below(2) == 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int s = 0; s < steps; ++s) x = std::nextafter(x, to);
    return x;
  }
  Vec3 perturbed(const Vec3& v) { return {perturbed(v.x), perturbed(v.y), perturbed(v.z)}; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace cc::test
