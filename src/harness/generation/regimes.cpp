// The regimes the library's certified error bounds cover, for the generators' bound-reaching
// constructions: sizes, aspect ratios up to 2^40, translations far beyond the shapes' size,
// frames at the orthonormality tolerance, nearly parallel frames, and the exact margin a
// construction is placed at.
#include "harness/generation/regimes.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "harness/generation/rotation.h"

namespace cc::harness {
namespace {

// A generic double in [1, 2): 52 random bits; the simplest is 1.
double generic_unit(Choices& c) { return 1 + static_cast<double>(c.draw(std::uint64_t{1} << 52)) * 0x1p-52; }

}  // namespace

double draw_size(ValueSource& v) {
  const double size = std::ldexp(1.0, v.small_int(20));
  return v.choices().chance(50) ? size : size * generic_unit(v.choices());
}

Vec3 draw_aspect_extents(ValueSource& v, double size) {
  Choices& c = v.choices();
  Vec3 half;
  for (int k = 0; k < 3; ++k) {
    switch (c.draw(4)) {
      case 0: half[k] = size; break;
      case 1: half[k] = size * generic_unit(c); break;
      case 2: half[k] = std::ldexp(size, -static_cast<int>(c.draw(41))); break;  // aspect up to 2^40
      default: {
        if (c.chance(30)) {
          half[k] = 0.0;
          break;
        }
        const int shift = static_cast<int>(c.draw(41));
        half[k] = std::ldexp(size * generic_unit(c), -shift);
      }
    }
  }
  return half;
}

Vec3 draw_direction(ValueSource& v) {
  Choices& c = v.choices();
  Vec3 d;
  for (int k = 0; k < 3; ++k) {
    const double sign = c.chance(50) ? -1.0 : 1.0;
    if (c.chance(20)) {
      d[k] = sign * 0.0;
      continue;
    }
    const double unit = generic_unit(c);
    d[k] = sign * (unit * std::ldexp(1.0, -static_cast<int>(c.draw(4))));
  }
  if (d == Vec3{}) d.x = 1;
  return d;
}

Vec3 draw_far_offset(ValueSource& v, double size) {
  Choices& c = v.choices();
  if (c.chance(40)) return {};
  // Up to 2^40 times the shapes' size (within every domain for sizes up to 2^20).
  const Vec3 direction = draw_direction(v);  // drawn before the length, as always
  return std::ldexp(size, static_cast<int>(c.draw(41))) * direction;
}

bool within_tolerance(const Mat3& m) {
  // The Gram matrix as computed is within 2.5u of exact (columns of length about 1).
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (std::fabs(dot(m.col[i], m.col[j]) - (i == j ? 1.0 : 0.0)) > kObbOrthonormalTolerance - 3 * fp::u) return false;
    }
  }
  return true;
}

Mat3 perturb_to_tolerance(ValueSource& v, const Mat3& rotation) {
  Choices& c = v.choices();
  // R (I + e/2 P) for a symmetric sign pattern P: the Gram matrix is I + e P + O(e^2), plus R's own
  // rounding (a few u), with e in [0.5, 0.7] of the tolerance.
  const double e = kObbOrthonormalTolerance * (0.5 + 0.2 * static_cast<double>(c.draw(1024)) / 1024);
  Mat3 s;
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      s(i, j) += (c.chance(50) ? -0.5 : 0.5) * e;
      s(j, i) = s(i, j);  // symmetric (on the diagonal, itself)
    }
  }
  Mat3 out;
  for (int j = 0; j < 3; ++j) out.col[j] = rotation * s.col[j];
  return within_tolerance(out) ? out : rotation;
}

Mat3 nearly_parallel(ValueSource& v, const Mat3& base) {
  Choices& c = v.choices();
  // A rotation by angle 2^-k about a generic axis, from its unit quaternion (cos, sin n).
  const int shift = 8 + static_cast<int>(c.draw(45));
  const double half_angle = std::ldexp(generic_unit(c), -shift);
  const Vec3 n = draw_direction(v);
  const double scale = std::sin(half_angle) / std::sqrt(dot(n, n));
  const Mat3 tilt = from_quaternion(std::cos(half_angle), scale * n.x, scale * n.y, scale * n.z);
  Mat3 out;
  for (int j = 0; j < 3; ++j) out.col[j] = base * tilt.col[j];
  return out;
}

MarginTarget draw_margin_target(Choices& c) {
  switch (c.draw(5)) {
    case 0:
    case 1: return {0, Side::inside};    // touching, or overlapping by less than a step
    case 2: return {0, Side::outside};   // apart by less than a step
    case 3: return {-std::ldexp(1.0, -static_cast<int>(40 + c.draw(14))), Side::inside};  // apart by 2^-40..2^-53
    default: return {std::ldexp(1.0, -static_cast<int>(40 + c.draw(14))), Side::outside};  // overlapping as much
  }
}

double place_at(const Family& family, double s_overlap, double s_apart, const MarginTarget& target,
                const GenerateOptions& options, double fallback) {
  if (options.exact == nullptr) return fallback;
  // A few dozen judgements place most cases on adjacent parameters; the rest end a little further.
  return bisect_to_margin(family, s_overlap, s_apart, target.margin, target.side, *options.exact, 32).value_or(fallback);
}

}  // namespace cc::harness
