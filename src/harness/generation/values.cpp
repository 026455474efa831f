#include "harness/generation/values.h"

#include <cmath>
#include <limits>

namespace cc::harness {
namespace {

// Zigzag order: 0, 1, -1, 2, -2, ...
long long zigzag(std::uint64_t i) {
  const auto h = static_cast<long long>((i + 1) / 2);
  return (i % 2 == 1) ? h : -h;
}

}  // namespace

int ValueSource::small_int(int limit) {
  return static_cast<int>(zigzag(choices_.draw(2 * static_cast<std::uint64_t>(limit) + 1)));
}

void PartsDrawn::add(Part p, long long parameter) {
  const auto i = static_cast<std::size_t>(p);
  ++times[i];
  if (parameter < least[i]) least[i] = parameter;
  if (parameter > greatest[i]) greatest[i] = parameter;
}

double ValueSource::nudge(double x) {
  const auto steps = 1 + choices_.draw(4);
  const double toward = choices_.chance(50) ? INFINITY : -INFINITY;
  for (std::uint64_t i = 0; i < steps; ++i) x = std::nextafter(x, toward);
  parts_.add(Part::nudge, static_cast<long long>(steps));
  return x;
}

double ValueSource::remember(double x, Part part, long long parameter) {
  if (part != Part::nudge) parts_.add(part, parameter);
  pool_.push_back(x);
  return x;
}

double ValueSource::coordinate() {
  const auto c = choices_.draw(100);
  if (c < 10) return remember(0.0, Part::zero);
  if (c < 25) {
    const int n = small_int(8);
    return remember(static_cast<double>(n), Part::small_integer, n);
  }
  if (c < 35) {
    const int quarters = small_int(32);
    return remember(static_cast<double>(quarters) / 4, Part::quarter, quarters);
  }
  if (c < 48 && !pool_.empty()) return remember(pool_[choices_.draw(pool_.size())], Part::repeat);
  if (c < 56 && !pool_.empty()) return remember(nudge(pool_[choices_.draw(pool_.size())]), Part::nudge);
  if (c < 64) {
    const double sign = choices_.chance(50) ? -1.0 : 1.0;
    const int exponent = small_int(24);
    return remember(sign * std::ldexp(1.0, exponent), Part::power_of_two, exponent);
  }
  if (c < 92 || !range_.extreme) {
    // A generic value: sign, mantissa, exponent; the simplest is 1.0.
    const double sign = choices_.chance(50) ? -1.0 : 1.0;
    const double mantissa = 1.0 + static_cast<double>(choices_.draw(std::uint64_t{1} << 52)) * 0x1p-52;
    const int exponent = small_int(range_.max_exponent);
    return remember(sign * std::ldexp(mantissa, exponent), Part::generic, exponent);
  }
  if (c < 94) return remember(-0.0, Part::minus_zero);
  const double sign = choices_.chance(50) ? -1.0 : 1.0;
  if (c < 96) {
    // Subnormals: the smallest, the largest, or one in between.
    switch (choices_.draw(3)) {
      case 0: return remember(sign * std::numeric_limits<double>::denorm_min(), Part::smallest_subnormal);
      case 1: return remember(sign * std::nextafter(std::numeric_limits<double>::min(), 0.0), Part::largest_subnormal);
      default: return remember(sign * std::ldexp(static_cast<double>(1 + choices_.draw(1u << 30)), -1074), Part::subnormal);
    }
  }
  const int e = 100 + static_cast<int>(choices_.draw(190));
  if (c < 98 || !(range_.huge || range_.special)) return remember(sign * std::ldexp(1.0, -e), Part::tiny, e);
  if (!range_.special || choices_.chance(50)) {
    return range_.huge ? remember(sign * std::ldexp(1.0, e), Part::huge, e) : remember(sign * std::ldexp(1.0, -e), Part::tiny, e);
  }
  switch (choices_.draw(3)) {
    case 0: return remember(std::numeric_limits<double>::quiet_NaN(), Part::nan);
    case 1: return remember(INFINITY, Part::infinity);
    default: return remember(-INFINITY, Part::minus_infinity);
  }
}

double ValueSource::length() {
  const auto c = choices_.draw(100);
  if (c < 15) return remember(0.0, Part::zero_length);
  if (c < 85) {  // a coordinate's magnitude: counted as that coordinate's part, remembered twice
    const double x = std::fabs(coordinate());
    pool_.push_back(x);
    return x;
  }
  // Sometimes a generic length of moderate size, so shapes have room to overlap.
  const int exponent = small_int(4);
  const double mantissa = 1.0 + static_cast<double>(choices_.draw(1u << 20)) * 0x1p-20;
  return remember(std::ldexp(mantissa, exponent), Part::moderate_length, exponent);
}

Vec3 ValueSource::point() {
  const double x = coordinate(), y = coordinate(), z = coordinate();
  return {x, y, z};
}

Vec3 with_one_component(Vec3 p, double x, Choices& c) {
  p[static_cast<int>(c.draw(3))] = x;
  return p;
}

}  // namespace cc::harness
