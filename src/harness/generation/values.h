// Boundary-biased doubles for the generators. Each value is drawn from a category, and the
// categories are ordered by simplicity, so shrinking the choices moves a value toward 0, then
// small integers, then halves, then values with fewer mantissa bits.
#pragma once

#include <array>
#include <climits>
#include <cstdint>
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

/// The parts of coordinate() and length(), each drawn by one branch. A test draws many values
/// and requires every part that the range allows to be drawn, and each part's parameter (a value,
/// an exponent, a number of steps) to reach both ends of its declared range: a branch that is
/// never taken, or a range shifted by one, cannot go unseen.
enum class Part {
  zero,               // 0
  small_integer,      // parameter: the integer, in [-8, 8]
  quarter,            // parameter: the number of quarters, in [-32, 32]
  repeat,             // an earlier value again
  nudge,              // parameter: the ULPs an earlier value is moved, in [1, 4]
  power_of_two,       // parameter: the exponent, in [-24, 24]
  generic,            // parameter: the exponent, in [-max_exponent, max_exponent]
  minus_zero,         // -0 (extreme)
  smallest_subnormal, // +-2^-1074 (extreme)
  largest_subnormal,  // +-(2^-1022 - 2^-1074) (extreme)
  subnormal,          // one in between (extreme)
  tiny,               // parameter: e of 2^-e, in [100, 289] (extreme)
  huge,               // parameter: e of 2^e, in [100, 289] (huge)
  nan,                // (special)
  infinity,           // (special)
  minus_infinity,     // (special)
  zero_length,        // a length of 0
  moderate_length,    // parameter: a length's exponent, in [-4, 4]
  count
};

/// The range each part's parameter is declared to cover, both ends included (Part::generic's is
/// [-max_exponent, max_exponent] of the ValueRange).
struct DeclaredRange {
  Part part;
  long long lo, hi;
};
inline constexpr DeclaredRange kDeclaredRanges[] = {
    {Part::small_integer, -8, 8}, {Part::quarter, -32, 32}, {Part::nudge, 1, 4},          {Part::power_of_two, -24, 24},
    {Part::tiny, 100, 289},       {Part::huge, 100, 289},   {Part::moderate_length, -4, 4}};

/// How often each part was drawn, and the least and greatest parameter it was drawn with.
struct PartsDrawn {
  std::array<std::uint64_t, static_cast<std::size_t>(Part::count)> times{};
  std::array<long long, static_cast<std::size_t>(Part::count)> least, greatest;
  PartsDrawn() {
    least.fill(LLONG_MAX);
    greatest.fill(LLONG_MIN);
  }
  void add(Part p, long long parameter = 0);
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
  /// The parts drawn so far.
  const PartsDrawn& parts() const { return parts_; }

 private:
  double remember(double x, Part part, long long parameter = 0);
  Choices& choices_;
  ValueRange range_;
  std::vector<double> pool_;
  PartsDrawn parts_;
};

/// `p` with one of its components, drawn from `c`, replaced by `x`: an out-of-contract case's
/// one bad coordinate (a NaN, an infinity, a negative extent).
Vec3 with_one_component(Vec3 p, double x, Choices& c);

}  // namespace cc::harness
