#include "collide/obb_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "collide/accurate_cross.h"
#include "collide/box_features.h"
#include "collide/depth_axes.h"
#include "collide/length.h"
#include "collide/nearest_pair.h"
#include "collide/obb_distance_bound.h"
#include "collide/record_sink.h"
#include "collide/segment.h"
#include "collide/segment_distance.h"
#include "collide/triangle.h"
#include "collide/triangle_distance.h"

namespace cc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The overlap of the boxes' projections on n over its length n_length (d = b.center - a.center):
// > 0 overlapping by that much, < 0 apart by that much; +infinity for a zero length (no
// information).
double overlap_on(const Obb& a, const Obb& b, const Vec3& d, const Vec3& n, double n_length) {
  if (!(n_length > 0)) return kInf;
  return ((radius_along(a, n) + radius_along(b, n)) - std::fabs(dot_in_order(d, n))) / n_length;
}

// The same on `direction`, scaled first: within ObbDistanceBound::evaluation() of the exact
// overlap on the computed direction.
double overlap_along(const Obb& a, const Obb& b, const Vec3& d, const Vec3& direction) {
  const Vec3 n = unit_scaled(direction);  // |n| in [1, 2 sqrt 3]: no underflow, no overflow
  return overlap_on(a, b, d, n, length(n));
}

// The same on a box's axis (axis_length, box_features.h).
double overlap_along_axis(const Obb& a, const Obb& b, const Vec3& d, const Vec3& axis) {
  return overlap_on(a, b, d, axis, axis_length(axis));
}

// The faces' axes, then the edge pairs', until one shows the boxes apart for certain (then the
// closest pair needs no more: its witnesses' gap is the tighter bound below).
using Axes = DepthAxes<15>;

Axes measure_axes(const Obb& a, const Obb& b, const Vec3& d, const bounds::ObbDistanceBound& bound) {
  Axes axes;
  const auto overlap = [&](const Vec3& n) { return overlap_along(a, b, d, n); };
  const auto face_overlap = [&](const Vec3& n) { return overlap_along_axis(a, b, d, n); };
  const double face_angle = 8 * kObbOrthonormalTolerance;
  for (int k = 0; k < 6; ++k) {
    axes.add((k % 2 == 0 ? a : b).axes.col[k / 2], bound.face_direction(), face_angle);
    axes.measure(axes.count - 1, face_overlap);
    if (axes.least_depth() + bound.evaluation() < 0) return axes;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 c = accurate_cross(a.axes.col[i], b.axes.col[j]);
      const double c_length = length(c);
      // Nearly parallel edges: measured when the direction's error costs less than the sliver.
      // An axis at least 1/2 long is always measured: the neighbours of a sliver's face are.
      const double sliver = bounds::ObbDistanceBound::sliver(std::min(a.half[i], b.half[j]), c_length);
      if (c_length < 0.5 && !(bound.cross_direction(c_length) < sliver)) {
        axes.sliver = std::max(axes.sliver, sliver);
        continue;
      }
      axes.add(c, bound.cross_direction(c_length), bounds::ObbDistanceBound::cross_angle(c_length));
      axes.measure(axes.count - 1, overlap);
      if (axes.least_depth() + bound.evaluation() < 0) return axes;
    }
  }
  return axes;
}

// Overlapping for certain: minus the least depth, the witnesses the nearest pair of a's feature
// farthest along the least axis and b's nearest along it, moved out by the depth.
Separation depth(const Obb& a, const Obb& b, const Vec3& d, const Axes& axes, double lower,
                 const bounds::ObbDistanceBound& bound) {
  const DepthAxis& least = axes.axis[axes.least];
  LengthAndDirection ld = length_and_direction(unit_scaled(least.n));
  Vec3 n = ld.direction;
  if (dot(d, n) < 0) n = -n;  // b is pushed along +n
  const double m = least.depth;
  const Vec3 shift = m * n;
  const double tolerance = 16 * fp::u + least.angle_error;
  Triangle on_a[2], on_b[2];
  const int na = farthest_feature(a, n, tolerance, {}, on_a);
  const int nb = farthest_feature(b, -n, tolerance, shift, on_b);
  // The features meet but for rounding: a pair of their triangles as near as the witnesses'
  // own bound ends the search (its gap joins that bound below).
  Separation nearest;
  nearest.distance = kInf;
  for (int k = 0; k < na * nb && !(nearest.distance <= bound.point()); ++k) {
    const Separation s = distance_triangle_triangle(on_a[k / nb], on_b[k % nb]);
    if (s.distance < nearest.distance) nearest = s;
  }
  // The pair meets where the least axis is a face of a - b; its gap counts in the witnesses'
  // bound, so that they are as far apart as the depth says within it.
  const double gap = nearest.distance;
  return {-m, nearest.on_a, nearest.on_b - shift, std::max(bound.evaluation(), m - lower),
          fp::sum3(bound.point(), gap / 2, 2 * fp::u * m)};
}

// The gap along the direction from the pair's first point to its second: a certified lower bound
// on the distance when positive (0 otherwise).
double gap_along(const Obb& a, const Obb& b, const Vec3& d, const NearestPair& pair, const bounds::ObbDistanceBound& bound) {
  const Vec3 along = pair.on_b - pair.on_a;
  if (along == Vec3{}) return 0;
  return std::max(0.0, -overlap_along(a, b, d, along) - bound.evaluation());
}

// The nearest of each corner against the other box and, unless the gap along the best pair's
// direction already proves it closest to within the rounding (its `gap`), of each pair of edges
// no farther from the other box than the best pair that reach beyond each other's faces.
NearestPair nearest_features(const Obb& a, const Obb& b, const Vec3& d, const bounds::ObbDistanceBound& bound,
                             double& gap) {
  const int exponent = bound.size > 0 ? fp::exponent_of(bound.size) : 0;
  const std::array<Vec3, 8> ca = corners(a), cb = corners(b);
  std::array<Vec3, 8> la, lb;  // the corners' coordinates in the other box
  // Each corner against the other box, compared in that box's frame (its axes orthonormal to
  // within 2^-48, the squares there agree with the world's far below the rounding the answer is
  // certified with): only the nearest is placed in the world.
  const auto square_out_of = [exponent](const Obb& box, const Vec3& q) {
    const Vec3 v = scaled(q - clamped(box, q), exponent);
    return dot_in_order(v, v);
  };
  double least = std::numeric_limits<double>::infinity();
  int nearest = 0;  // a's corner i as i, b's as 8 + i
  for (int i = 0; i < 8; ++i) {
    la[i] = box_coordinates(b, ca[i]), lb[i] = box_coordinates(a, cb[i]);
    if (const double s = square_out_of(b, la[i]); s < least) least = s, nearest = i;
    if (const double s = square_out_of(a, lb[i]); s < least) least = s, nearest = 8 + i;
  }
  NearestPair best;
  best.exponent = exponent;
  if (nearest < 8) {
    best.keep_nearer(ca[nearest], clamped_into(b, la[nearest]));
  } else {
    best.keep_nearer(clamped_into(a, lb[nearest - 8]), cb[nearest - 8]);
  }
  gap = gap_along(a, b, d, best, bound);
  if (best.proven_by(gap)) return best;
  // Edge k of a box joins corner i (bit k clear) and i | 1 << k. Each edge's extent in the other
  // box's frame; those no farther from the other box than the best pair, paired where each
  // reaches beyond the other's faces (reaches_beyond, box_features.h).
  struct Edge {
    int axis, from, to;
    Extent extent;
  };
  std::array<Edge, 12> ea, eb;
  int na = 0, nb = 0;
  const Extent whole_a{-a.half, a.half}, whole_b{-b.half, b.half};
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 8; ++i) {
      if (i >> k & 1) continue;
      const int j = i | 1 << k;
      const Extent in_b = extent_of(la[i], la[j]), in_a = extent_of(lb[i], lb[j]);
      if (best.may_improve_on(square_gap(in_b, whole_b, exponent))) ea[na++] = {k, i, j, in_b};
      if (best.may_improve_on(square_gap(in_a, whole_a, exponent))) eb[nb++] = {k, i, j, in_a};
    }
  }
  const double margin = 0x1p-30 * bound.size;
  for (int i = 0; i < na; ++i) {
    const Segment sa{ca[ea[i].from], ca[ea[i].to]};
    for (int j = 0; j < nb; ++j) {
      if (!reaches_beyond(b, ea[i].extent, eb[j].from, eb[j].axis, margin) ||
          !reaches_beyond(a, eb[j].extent, ea[i].from, ea[i].axis, margin)) {
        continue;
      }
      const Segment sb{cb[eb[j].from], cb[eb[j].to]};
      const auto [s, t] = closest_segment_parameters(sa, sb);
      best.keep_nearer(sa.a + s * (sa.b - sa.a), sb.a + t * (sb.b - sb.a));
    }
  }
  gap = gap_along(a, b, d, best, bound);
  return best;
}

// Apart, or not certainly overlapping: the nearest pair, certified after the fact. Below: the
// gap on the witnesses' direction when positive (then they are apart) and, on every axis, the
// signed distance is at least minus its overlap. Where they may overlap, a witness may lie in
// the other box by up to the depth, which joins the witnesses' bound.
Separation closest(const Obb& a, const Obb& b, const Vec3& d, const Axes& axes, const bounds::ObbDistanceBound& bound) {
  double gap = 0;
  const NearestPair best = nearest_features(a, b, d, bound, gap);
  const double least = axes.least_depth();
  double lower = -(least + bound.evaluation());
  if (gap > 0) lower = std::max(lower, gap);
  return Separation::certified(best.on_a, best.on_b, bound.point() + std::max(0.0, least + bound.evaluation()), lower);
}

template <class Records>
Separation obb_obb(const Obb& a, const Obb& b, Records& records) {
  if (!in_domain(a) || !in_domain(b)) return Separation::outside_the_domain();
  const Vec3 d = b.center - a.center;
  const bounds::ObbDistanceBound bound{fp::sum3(norm1(d), norm1(a.half), norm1(b.half)) * (1 + 8 * fp::u),
                                       std::max(max_abs(a.center), max_abs(b.center))};
  const Axes axes = measure_axes(a, b, d, bound);
  const double lower = axes.certain_depth(bound.evaluation());
  const Separation s = lower > 0 ? depth(a, b, d, axes, lower, bound) : closest(a, b, d, axes, bound);
  records.add(bounds::ObbSeparation{a, b, s, bound});
  return s;
}

}  // namespace

Separation distance_obb_obb(const Obb& a, const Obb& b) {
  bounds::NoRecords none;
  return obb_obb(a, b, none);
}

Separation distance_obb_obb(const Obb& a, const Obb& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return obb_obb(a, b, into);
}

}  // namespace cc
