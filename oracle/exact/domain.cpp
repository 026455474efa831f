#include "oracle/exact/domain.h"

#include <cmath>
#include <limits>

#include "oracle/exact/bounded.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

harness::ExactVerdict documented(bool answer, std::string why) {
  harness::ExactVerdict v;
  v.contract = harness::Contract::documented;
  v.answer.hit = answer;
  v.margin = NAN;
  v.note = std::move(why);
  return v;
}

harness::ExactVerdict unspecified(std::string why) {
  harness::ExactVerdict v;
  v.contract = harness::Contract::unspecified;
  v.decided = false;  // no verdict: the reference gives no answer here
  v.margin = NAN;
  v.note = std::move(why);
  return v;
}

harness::ExactVerdict beyond_range(harness::ExactVerdict decided, std::string why) {
  decided.contract = harness::Contract::unspecified;
  decided.note = std::move(why);
  return decided;
}

bool has_nan(std::initializer_list<double> values) {
  for (double v : values) {
    if (std::isnan(v)) return true;
  }
  return false;
}

bool all_finite(std::initializer_list<double> values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

bool all_finite(const Triangle& t) {
  for (const Vec3& p : t.v) {
    if (!all_finite({p.x, p.y, p.z})) return false;
  }
  return true;
}

bool all_finite(const Obb& b) {
  for (const Vec3& v : {b.center, b.half, b.axes.col[0], b.axes.col[1], b.axes.col[2]}) {
    if (!all_finite({v.x, v.y, v.z})) return false;
  }
  return true;
}

double scale_of(double largest_magnitude) { return largest_magnitude > 0 ? largest_magnitude : 1.0; }

double signed_margin(double rounded, int exact_sign) {
  if (exact_sign == 0 || rounded != 0) return rounded;
  return exact_sign > 0 ? std::numeric_limits<double>::denorm_min() : -std::numeric_limits<double>::denorm_min();
}

std::optional<std::string> scale_outside(double largest_magnitude, int min_exponent, int max_exponent) {
  if (largest_magnitude > std::ldexp(1.0, max_exponent)) {
    return "a coordinate exceeds 2^" + std::to_string(max_exponent) + " in magnitude";
  }
  if (largest_magnitude > 0 && largest_magnitude < std::ldexp(1.0, min_exponent)) {
    return "every coordinate is below 2^" + std::to_string(min_exponent) + " in magnitude";
  }
  return std::nullopt;
}

std::optional<std::string> not_orthonormal(const Mat3& axes) {
  const Rational tolerance = rational(kObbOrthonormalTolerance);
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      // In floating point when the entry's bound puts it clearly inside the tolerance.
      const Bounded filtered = dot(exactly(axes.col[i]), exactly(axes.col[j])) - exactly(i == j ? 1.0 : 0.0);
      if (filtered.finite() && std::fabs(filtered.v) + filtered.e < kObbOrthonormalTolerance * (1 - 0x1p-40)) continue;
      Rational g = dot(rational(axes.col[i]), rational(axes.col[j]));
      if (i == j) g -= 1;
      if (abs(g) > tolerance) {
        return "axes not orthonormal: entry (" + std::to_string(i) + "," + std::to_string(j) +
               ") of axes^T axes - I is " + std::to_string(to_double(g));
      }
    }
  }
  return std::nullopt;
}

}  // namespace cc::exact
