// MeasuredVector, through length() and length_and_direction(): the common case (|v|^2 in
// [2^-998, 2^1000], no scaling looked for) gives the same bits as the scaled measurement, at both ends of that range and beyond them,
// and lengths and directions stay accurate from the subnormal range to the largest doubles.
#include "collide/length.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

namespace cc {
namespace {

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

// The measurement as MeasuredVector's contract states it, whatever the sum of squares: scaled
// exactly when the largest component lies outside [2^-500, 2^500].
LengthAndDirection scaled_measurement(const Vec3& v) {
  const double m = max_abs(v);
  const int e = m > 0 && (m < 0x1p-500 || m > 0x1p500) ? fp::exponent_of(m) : 0;
  const Vec3 w = scaled(v, e);
  const double n = std::sqrt(fp::sum3(w.x * w.x, w.y * w.y, w.z * w.z));
  if (!(n > 0)) return {};
  const double inverse = 1 / n;
  return {fp::scale2(n, e), {w.x * inverse, w.y * inverse, w.z * inverse}};
}

TEST(MeasuredVector, TheCommonCaseToldByTheSumOfSquaresGivesTheScaledMeasurementBitForBit) {
  const double ends[] = {0x1p-499, 0x1p-500, std::nextafter(0x1p-500, 0), 0x1.6a09e667f3bcdp-500,
                         0x1.6a09e667f3bcdp-501, 0x1p500, std::nextafter(0x1p500, 1e300), 0x1.6a09e667f3bcdp499,
                         0x1.6a09e667f3bcdp-530, 0x1p-1074, 0x1.fffffffffffffp1023, 1, 0.1};
  int common = 0, beyond = 0;
  for (const double e : ends) {
    for (const Vec3& v : {Vec3{e, 0, 0}, Vec3{e, -e, e}, Vec3{0.3 * e, -e, 0.7 * e}, Vec3{0, 0, -e}}) {
      const LengthAndDirection got = length_and_direction(v), want = scaled_measurement(v);
      EXPECT_TRUE(same_bits(got.length, want.length)) << e << ": " << got.length << " against " << want.length;
      for (int i = 0; i < 3; ++i) EXPECT_TRUE(same_bits(got.direction[i], want.direction[i])) << e << " at " << i;
      EXPECT_TRUE(same_bits(length(v), want.length)) << e;
      const double s = fp::sum3(v.x * v.x, v.y * v.y, v.z * v.z);
      (s >= 0x1p-998 && s <= 0x1p1000 ? common : beyond) += 1;
    }
  }
  EXPECT_GE(common, 10);  // both ways taken
  EXPECT_GE(beyond, 10);
}

TEST(MeasuredVector, IsAccurateAtEveryScaleAndZeroHasNoDirection) {
  for (const double scale : {0x1p-1070, 0x1p-600, 0x1p-499, 1.0, 0x1p499, 0x1p600, 0x1p1020}) {
    const LengthAndDirection ld = length_and_direction({3 * scale, 0, -4 * scale});
    EXPECT_NEAR(ld.length / scale, 5, 5 * 3e-16) << scale;
    EXPECT_NEAR(ld.direction.x, 0.6, 1e-15) << scale;
    EXPECT_NEAR(ld.direction.z, -0.8, 1e-15) << scale;
  }
  const LengthAndDirection zero = length_and_direction({0, -0.0, 0});
  EXPECT_EQ(zero.length, 0);
  EXPECT_EQ(zero.direction, Vec3{});
}

}  // namespace
}  // namespace cc
