// Random numbers from a seed that are the same on every platform: std's distributions differ
// between standard libraries, so doubles come from the raw 64-bit outputs of mt19937_64.
#pragma once

#include <cstdint>
#include <random>

namespace cc {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}
  /// A double in [0, 1), a multiple of 2^-53.
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  double between(double lo, double hi) { return lo + (hi - lo) * unit(); }
  /// An integer in [0, n), n > 0.
  std::uint64_t below(std::uint64_t n) { return engine_() % n; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace cc
