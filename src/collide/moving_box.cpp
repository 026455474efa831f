#include "collide/moving_box.h"

#include <cmath>
#include <limits>
#include <utility>

#include "collide/obb_bound.h"
#include "collide/record_sink.h"
#include "collide/sweep_bound.h"

namespace cc {
namespace {

// A closed interval of times; empty when enter > exit.
struct TimeWindow {
  double enter, exit;
};
constexpr TimeWindow kAlways{-INFINITY, INFINITY};
constexpr TimeWindow kNever{INFINITY, -INFINITY};
constexpr TimeWindow kStep{0, 1};

TimeWindow intersection(TimeWindow x, TimeWindow y) { return {std::max(x.enter, y.enter), std::min(x.exit, y.exit)}; }
bool empty(TimeWindow x) { return !(x.enter <= x.exit); }
// The smallest window holding both (an empty one leaves the other as it is).
TimeWindow hull(TimeWindow x, TimeWindow y) {
  if (empty(x)) return y;
  if (empty(y)) return x;
  return {std::min(x.enter, y.enter), std::max(x.exit, y.exit)};
}

// ---- Oriented boxes ----

// One axis: at time t the centres' offset projects to projection + t * rate and the boxes to
// radius_a and radius_b, each within `error` of its exact value for every t in [0, 1]. The
// times at which the projections may overlap: |projection + t rate| <= radius_a + radius_b +
// error, widened for the rounding of solving for them.
template <class Records>
TimeWindow overlap_window(double projection, double rate, double radius_a, double radius_b, double error,
                          Records& records) {
  if (rate == 0) {  // test_obb_obb's criterion, for the whole step
    return std::fabs(projection) - (radius_a + radius_b) > error ? kNever : kAlways;
  }
  // reach rounds once, by less than u (radius_a + radius_b): error's 32u exceeds the 30u that
  // the projections and radii need by more than that.
  const double reach = (radius_a + radius_b) + error;
  double enter = (-reach - projection) / rate, exit = (reach - projection) / rate;
  records.add(bounds::Quotient{-reach, projection, rate, 0, 0, enter, bounds::kSweepObbTime});
  records.add(bounds::Quotient{reach, projection, rate, 0, 0, exit, bounds::kSweepObbTime});
  if (rate < 0) std::swap(enter, exit);
  // Each time is a difference of two doubles divided by a third, two roundings: within 2.0001u
  // of its exact value (bounds::kSweepObbTime).
  return {bounds::kSweepObbTime.lower(enter), bounds::kSweepObbTime.upper(exit)};
}

bool in_contract(const MovingObb& m) {
  return in_domain(m.box) && finite(m.velocity);
}

// ---- Axis-aligned boxes ----

// A rounded result and whether it is exact.
struct Rounded {
  double value;
  bool exact;
};

// x - y, exact when Knuth's two-sum finds its rounding error to be 0 (two-sum is error-free for
// any finite operands in round-to-nearest, whatever their order of magnitude).
Rounded difference(double x, double y) {
  const double s = x - y;
  const double y_virtual = s - x;  // the part of s that stands for -y
  const double x_virtual = s - y_virtual;
  const double rounding = (x - x_virtual) + (-y - y_virtual);
  return {s, rounding == 0};
}

// n / d (d != 0), exact when n and d are and the remainder n - q d is 0. The fused multiply-add
// rounds the exact remainder once; when |n| >= 2^-960 the remainder is a multiple of a power of
// two >= 2^-1074 (q d is close to n, so the exponents of q and d add up to about that of n), and
// if nonzero it does not round to 0.
Rounded quotient(Rounded n, Rounded d) {
  const double q = n.value / d.value;
  const bool remainder_zero = n.value == 0 || (std::fabs(n.value) >= 0x1p-960 && std::fma(-q, d.value, n.value) == 0);
  return {q, n.exact && d.exact && remainder_zero};
}

// One coordinate axis: the slabs [a_lo + t va, a_hi + t va] and [b_lo + t vb, b_hi + t vb]
// overlap iff a_lo - b_hi <= t (vb - va) <= a_hi - b_lo.
template <class Records>
TimeWindow slab_window(double a_lo, double a_hi, double va, double b_lo, double b_hi, double vb, Records& records) {
  if (va == vb) return a_lo <= b_hi && b_lo <= a_hi ? kAlways : kNever;  // rate 0: exact
  const Rounded rate = difference(vb, va);  // nonzero, and of the exact sign
  Rounded enter = quotient(difference(a_lo, b_hi), rate), exit = quotient(difference(a_hi, b_lo), rate);
  records.add(bounds::Quotient{a_lo, b_hi, vb, va, 0, enter.value, bounds::kSweepAabbTime});
  records.add(bounds::Quotient{a_hi, b_lo, vb, va, 0, exit.value, bounds::kSweepAabbTime});
  if (rate.value < 0) std::swap(enter, exit);
  // Three roundings: within 3.000001u of the exact time (bounds::kSweepAabbTime).
  return {enter.exact ? enter.value : bounds::kSweepAabbTime.lower(enter.value),
          exit.exact ? exit.value : bounds::kSweepAabbTime.upper(exit.value)};
}

bool in_contract(const Aabb& box, const Vec3& velocity) {
  return finite(box.lo) && finite(box.hi) && finite(velocity) && box.lo.x <= box.hi.x && box.lo.y <= box.hi.y &&
         box.lo.z <= box.hi.z;
}

// x - y rounded up: at least the exact difference.
double difference_up(double x, double y) {
  const Rounded r = difference(x, y);
  return r.exact ? r.value : std::nextafter(r.value, INFINITY);
}

}  // namespace

MovingObb moving_obb(const Aabb& box, const Vec3& velocity) {
  Obb obb;  // identity axes
  for (int k = 0; k < 3; ++k) {
    const double lo = box.lo[k], hi = box.hi[k];
    obb.center[k] = 0.5 * (lo + hi);
    obb.half[k] = lo <= hi ? std::max(difference_up(hi, obb.center[k]), difference_up(obb.center[k], lo))
                           : std::numeric_limits<double>::quiet_NaN();  // also for NaN bounds
  }
  return {obb, velocity};
}

namespace {

template <class Records>
SweepHit sweep_obb(const MovingObb& a, const MovingObb& b, Records& records) {
  const Obb &box_a = a.box, &box_b = b.box;
  const Vec3 d = box_b.center - box_a.center;  // swapping a and b negates d and v exactly
  const Vec3 v = b.velocity - a.velocity;
  double r[3][3], abs_r[3][3];  // r[i][j] = a_i . b_j
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      r[i][j] = dot(box_a.axes.col[i], box_b.axes.col[j]);
      abs_r[i][j] = std::fabs(r[i][j]);
    }
  }
  // The offset and the relative velocity in a's frame and in b's frame. Each projection below is
  // the same expression in d (its value at t = 0) and in v (its rate).
  const Vec3 d_in_a = transpose_times(box_a.axes, d), d_in_b = transpose_times(box_b.axes, d);
  const Vec3 v_in_a = transpose_times(box_a.axes, v), v_in_b = transpose_times(box_b.axes, v);

  // test_obb_obb's bound, with |v|_1 beside |d|_1: a projection at t is (value at 0) + t (rate),
  // each rate computed like its value, so for t in [0, 1] its rounding is at most
  // 22u (|d|_1 + |v|_1) + 8u (sum of half extents). Frame: as in test_obb_obb. With v = 0 this
  // is test_obb_obb's bound bit for bit.
  const double sum_a = fp::sum3(box_a.half.x, box_a.half.y, box_a.half.z);
  const double sum_b = fp::sum3(box_b.half.x, box_b.half.y, box_b.half.z);
  const bounds::ObbBound bound{norm1(d) + norm1(v), sum_a, sum_b};
  records.add(bounds::ObbTest{a, b, bound});
  const double error = bound.total();

  TimeWindow window = kStep;
  for (int i = 0; i < 3; ++i) {  // a's face normals
    const double rb = fp::sum3(box_b.half.x * abs_r[i][0], box_b.half.y * abs_r[i][1], box_b.half.z * abs_r[i][2]);
    records.add(bounds::ObbAxis{i, 0, d_in_a[i], v_in_a[i], box_a.half[i], rb});
    window = intersection(window, overlap_window(d_in_a[i], v_in_a[i], box_a.half[i], rb, error, records));
  }
  for (int j = 0; j < 3; ++j) {  // b's face normals
    const double ra = fp::sum3(box_a.half.x * abs_r[0][j], box_a.half.y * abs_r[1][j], box_a.half.z * abs_r[2][j]);
    records.add(bounds::ObbAxis{3 + j, 0, d_in_b[j], v_in_b[j], ra, box_b.half[j]});
    window = intersection(window, overlap_window(d_in_b[j], v_in_b[j], ra, box_b.half[j], error, records));
  }
  for (int i = 0; i < 3; ++i) {  // a_i x b_j
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      // Projections onto a_i x b_j in a's frame and in b's frame, as in test_obb_obb. Each frame
      // gives a valid interval; like test_obb_obb (which separates only if both frames do), the
      // axis keeps every time of the step that either frame keeps. (Each is cut to the step
      // first: the hull of two windows outside the step, one before and one after, would hold
      // the whole step.)
      const auto in_a = [&](const Vec3& w) { return w[i2] * r[i1][j] - w[i1] * r[i2][j]; };
      const auto in_b = [&](const Vec3& w) { return r[i][j2] * w[j1] - r[i][j1] * w[j2]; };
      const double ra = box_a.half[i1] * abs_r[i2][j] + box_a.half[i2] * abs_r[i1][j];
      const double rb = box_b.half[j1] * abs_r[i][j2] + box_b.half[j2] * abs_r[i][j1];
      records.add(bounds::ObbAxis{6 + 3 * i + j, 0, in_a(d_in_a), in_a(v_in_a), ra, rb});
      records.add(bounds::ObbAxis{6 + 3 * i + j, 1, in_b(d_in_b), in_b(v_in_b), ra, rb});
      window = intersection(
          window, hull(intersection(kStep, overlap_window(in_a(d_in_a), in_a(v_in_a), ra, rb, error, records)),
                       intersection(kStep, overlap_window(in_b(d_in_b), in_b(v_in_b), ra, rb, error, records))));
    }
  }
  if (empty(window)) return {};
  if (!in_contract(a) || !in_contract(b)) return {};  // checked on the hit path only
  return {true, window.enter + 0.0, window.exit + 0.0};  // + 0.0: a time 0 is +0
}

template <class Records>
SweepHit sweep_aabb(const Aabb& a, const Vec3& va, const Aabb& b, const Vec3& vb, Records& records) {
  TimeWindow window = kStep;
  for (int k = 0; k < 3; ++k) {
    window = intersection(window, slab_window(a.lo[k], a.hi[k], va[k], b.lo[k], b.hi[k], vb[k], records));
  }
  if (!(window.enter <= window.exit)) return {};
  if (!in_contract(a, va) || !in_contract(b, vb)) return {};
  return {true, window.enter + 0.0, window.exit + 0.0};
}

}  // namespace

SweepHit sweep_obb_obb(const MovingObb& a, const MovingObb& b) {
  bounds::NoRecords none;
  return sweep_obb(a, b, none);
}

SweepHit sweep_obb_obb(const MovingObb& a, const MovingObb& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return sweep_obb(a, b, into);
}

SweepHit sweep_aabb_aabb(const Aabb& a, Vec3 va, const Aabb& b, Vec3 vb) {
  bounds::NoRecords none;
  return sweep_aabb(a, va, b, vb, none);
}

SweepHit sweep_aabb_aabb(const Aabb& a, Vec3 va, const Aabb& b, Vec3 vb, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return sweep_aabb(a, va, b, vb, into);
}

}  // namespace cc
