// Boundary-biased doubles for the generators. Each value is drawn from a category, and the
// categories are ordered by simplicity, so shrinking the choices moves a value toward 0, then
// small integers, then halves, then values with fewer mantissa bits.
#pragma once

#include <vector>

#include "collide/vec3.h"
#include "harness/generation/choices.h"

namespace cc::harness {

/// What a generated value may be.
struct ValueRange {
  int max_exponent = 8;  // "generic" values have magnitude below 2^max_exponent
  bool extreme = true;   // also subnormals, -0 and tiny values (2^-290 .. 2^-100)
  bool huge = false;     // also huge values (2^100 .. 2^290): they dwarf every other coordinate
  bool special = false;  // also NaN and infinities (out-of-contract properties)
};

/// Draws values for one case and remembers them, so that later values can repeat an earlier
/// one exactly or sit a few ULPs from it (equal coordinates are where boundaries are).
class ValueSource {
 public:
  ValueSource(Choices& choices, ValueRange range) : choices_(choices), range_(range) {}

  /// A coordinate: 0, a small integer, a half or quarter, an earlier value (or a few ULPs from
  /// it), a power of two, a generic double; with range.extreme -0, subnormals and tiny values;
  /// with range.huge huge values; with range.special NaN and infinities.
  double coordinate();
  /// A non-negative length (extent, radius): 0 is the most likely simple value.
  double length();
  Vec3 point();
  /// A small integer in [-limit, limit], zigzag ordered from 0.
  int small_int(int limit);
  /// x moved by 1 to 4 ULPs in either direction.
  double nudge(double x);

  Choices& choices() { return choices_; }
  const ValueRange& range() const { return range_; }

 private:
  double remember(double x);
  Choices& choices_;
  ValueRange range_;
  std::vector<double> pool_;
};

}  // namespace cc::harness
