#include "collide/triangle_box_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "collide/accurate_cross.h"
#include "collide/box_features.h"
#include "collide/depth_axes.h"
#include "collide/length.h"
#include "collide/nearest_pair.h"
#include "collide/record_sink.h"
#include "collide/segment.h"
#include "collide/segment_distance.h"
#include "collide/triangle_box_distance_bound.h"
#include "collide/triangle_distance.h"
#include "collide/triangle_foot.h"

namespace cc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using Bound = bounds::TriangleBoxDistanceBound;
using Axes = DepthAxes<13>;

// The triangle's vertices less the box's centre, as computed.
using Relative = std::array<Vec3, 3>;

// The extremes of the triangle's projection on n.
struct Interval {
  double lo, hi;
};
Interval projection(const Relative& w, const Vec3& n) {
  const double p0 = dot_in_order(w[0], n), p1 = dot_in_order(w[1], n), p2 = dot_in_order(w[2], n);
  return {std::min({p0, p1, p2}), std::max({p0, p1, p2})};
}

// The overlap of the projections of the triangle (w) and the box (centred at 0) on `direction`
// over its length: > 0 overlapping by that much, < 0 apart by that much; +infinity for a zero
// direction (no information). Within Bound::evaluation() of the exact overlap on the computed
// direction.
double overlap_on(const Relative& w, const Obb& box, const Vec3& n, double n_length) {
  if (!(n_length > 0)) return kInf;
  const double r = radius_along(box, n);
  const Interval t = projection(w, n);
  return std::min(t.hi + r, r - t.lo) / n_length;
}
double overlap_along(const Relative& w, const Obb& box, const Vec3& direction) {
  const Vec3 n = unit_scaled(direction);  // |n| in [1, 2 sqrt 3]: no underflow, no overflow
  return overlap_on(w, box, n, length(n));
}

// The same on one of the box's axes (axis_length, box_features.h).
double overlap_along_axis(const Relative& w, const Obb& box, const Vec3& axis) {
  return overlap_on(w, box, axis, axis_length(axis));
}

// The box's axes, then the triangle's normal and its edges' cross products with the box's axes,
// until one shows the shapes apart for certain (then the closest pair needs no more).
Axes measure_axes(const Triangle& t, const Relative& w, const Obb& box, const Bound& bound) {
  Axes axes;
  const auto overlap = [&](const Vec3& n) { return overlap_along(w, box, n); };
  const auto face_overlap = [&](const Vec3& n) { return overlap_along_axis(w, box, n); };
  const double face_angle = 8 * kObbOrthonormalTolerance;
  for (int k = 0; k < 3; ++k) {
    axes.add(box.axes.col[k], bound.face_direction(), face_angle);
    axes.measure(k, face_overlap);
    if (axes.least_depth() + bound.evaluation() < 0) return axes;
  }
  std::array<ExactDifference, 3> edge;  // edge k from v[k] to v[k + 1], exactly, scaled
  std::array<double, 3> edge_length;    // as given, not scaled
  for (int k = 0; k < 3; ++k) {
    const ExactDifference e = exact_difference(t.v[(k + 1) % 3], t.v[k]);
    edge[k] = unit_scaled(e);
    edge_length[k] = length(e.hi);
  }
  const Vec3 normal = accurate_cross(edge[0], edge[1]);
  const double normal_length = length(normal);
  // Each axis measured as it comes: one that shows them apart for certain ends the list.
  const auto apart_on = [&](const Vec3& n, double angle) {
    axes.add(n, bound.direction(angle), angle);
    axes.measure(axes.count - 1, overlap);
    return axes.least_depth() + bound.evaluation() < 0;
  };
  if (normal_length > 0 && apart_on(normal, Bound::normal_angle(normal_length))) return axes;
  for (int k = 0; k < 3; ++k) {
    const double scaled_length = length(edge[k].hi);
    if (!(scaled_length > 0)) continue;  // a repeated vertex: no edge
    for (int j = 0; j < 3; ++j) {
      const Vec3 c = accurate_cross(edge[k], box.axes.col[j]);
      const double c_length = length(c), sine = c_length / scaled_length;
      // Nearly parallel: measured when the direction's error costs less than the sliver. An
      // axis whose sine is at least 1/2 is always measured: the neighbours of a sliver's face are
      // (the box's faces, the triangle's, and edge pairs of the other axes), or are slivers
      // themselves, whose widths add up.
      const double sliver = Bound::sliver(std::min(box.half[j], edge_length[k] / 2), sine);
      if (sine < 0.5 && !(bound.direction(Bound::edge_angle(c_length)) < sliver)) {
        axes.sliver += sliver;
        continue;
      }
      if (apart_on(c, Bound::edge_angle(c_length))) return axes;
    }
  }
  return axes;
}

// Overlapping for certain: minus the least depth; the witnesses the nearest pair of the
// triangle's vertices farthest along the least axis and the box's feature nearest along it,
// the box moved out by the depth.
Separation depth(const Triangle& t, const Relative& w, const Obb& box, const Axes& axes, double lower,
                 const Bound& bound) {
  const DepthAxis& least = axes.axis[axes.least];
  Vec3 n = length_and_direction(unit_scaled(least.n)).direction;
  const Interval along = projection(w, n);
  const bool flip = along.hi > -along.lo;  // the box is pushed along +n, away from the triangle
  if (flip) n = -n;
  const double farthest = flip ? -along.lo : along.hi;  // the triangle's, along the new n
  const double m = least.depth;
  const Vec3 shift = m * n;
  const double tolerance = 16 * fp::u + least.angle_error;
  // The vertices within the tolerance of the farthest, as a triangle (repeating one or two).
  Triangle on_t = t;
  int kept = 0;
  for (int k = 0; k < 3; ++k) {
    if (farthest - dot(w[k], n) <= tolerance * bound.size) on_t.v[kept++] = t.v[k];
  }
  for (int k = kept; k < 3; ++k) on_t.v[k] = on_t.v[k - 1];
  Triangle on_box[2];
  const int count = farthest_feature(box, -n, tolerance, shift, on_box);
  // The features meet but for rounding: a triangle of the box's feature as near as the
  // witnesses' own bound ends the search (its gap joins that bound below).
  Separation nearest;
  nearest.distance = kInf;
  for (int i = 0; i < count && !(nearest.distance <= bound.point()); ++i) {
    const Separation s = distance_triangle_triangle(on_t, on_box[i]);
    if (s.distance < nearest.distance) nearest = s;
  }
  // The pair meets where the least axis is a face of the difference; its gap counts in the
  // witnesses' bound, so that they are as far apart as the depth says within it.
  const double gap = nearest.distance;
  return {-m, nearest.on_a, nearest.on_b - shift, std::max(bound.evaluation(), m - lower),
          fp::sum3(bound.point(), gap / 2, 2 * fp::u * m)};
}

// The gap along the direction from the pair's first point to its second: a certified lower bound
// on the distance when positive (0 otherwise).
double gap_along(const Relative& w, const Obb& box, const NearestPair& pair, const Bound& bound) {
  const Vec3 along = pair.on_b - pair.on_a;
  if (along == Vec3{}) return 0;
  return std::max(0.0, -overlap_along(w, box, along) - bound.evaluation());
}

// The nearest of each vertex against the box, each corner of the box against the triangle's face
// (those the triangle reaches beyond and nearer its plane than the best pair), and, unless the gap
// along the best pair's direction already proves it closest to within the rounding (its `gap`),
// each pair of a triangle edge and a box edge that the edge reaches beyond and whose extents in
// the box's frame are not farther apart than the best pair.
NearestPair nearest_features(const Triangle& t, const Relative& w, const Obb& box, const Bound& bound, double& gap) {
  const int exponent = bound.size > 0 ? fp::exponent_of(bound.size) : 0;
  const std::array<Vec3, 8> corner = corners(box);  // bit k of an index set for +half_k
  std::array<Vec3, 3> local;                        // the vertices in the box's frame
  NearestPair best;
  best.exponent = exponent;
  for (int k = 0; k < 3; ++k) {
    local[k] = box_coordinates(box, t.v[k]);
    best.keep_nearer(t.v[k], clamped_into(box, local[k]));
  }
  // A box feature can be nearest to a point of the triangle only if the triangle reaches beyond
  // its faces (reaches_beyond, box_features.h).
  Extent triangle = extent_of(local[0], local[1]);
  for (int k = 0; k < 3; ++k) {
    triangle.lo[k] = std::min(triangle.lo[k], local[2][k]), triangle.hi[k] = std::max(triangle.hi[k], local[2][k]);
  }
  const double margin = 0x1p-30 * bound.size;
  const Vec3 normal = unit_scaled(cross(t.v[1] - t.v[0], t.v[2] - t.v[0]));  // for pruning only
  const double normal_square = dot_in_order(normal, normal);
  for (int i = 0; i < 8; ++i) {
    if (!reaches_beyond(box, triangle, i, -1, margin)) continue;
    const Vec3& c = corner[i];
    if (normal_square > 0) {
      const double height = fp::scale2(dot_in_order(c - t.v[0], normal), -exponent);
      if (!best.may_improve_on(height * height / normal_square)) continue;
    }
    Vec3 foot;
    if (foot_in_triangle(c, t, foot)) best.keep_nearer(foot, c);
  }
  gap = gap_along(w, box, best, bound);
  if (best.proven_by(gap)) return best;
  // Box edge j from corner i (bit j clear) to i | 1 << j.
  for (int e = 0; e < 3; ++e) {
    const Extent on_edge = extent_of(local[e], local[(e + 1) % 3]);
    if (!best.may_improve_on(square_gap(on_edge, {-box.half, box.half}, exponent))) continue;
    const Segment edge{t.v[e], t.v[(e + 1) % 3]};
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 8; ++i) {
        if (i >> j & 1) continue;
        if (!reaches_beyond(box, on_edge, i, j, margin)) continue;
        if (!best.may_improve_on(square_gap(on_edge, edge_extent(box, j, i), exponent))) continue;
        const Segment sb{corner[i], corner[i | 1 << j]};
        const auto [s, u] = closest_segment_parameters(edge, sb);
        best.keep_nearer(edge.a + s * (edge.b - edge.a), sb.a + u * (sb.b - sb.a));
      }
    }
  }
  gap = gap_along(w, box, best, bound);
  return best;
}

// Apart, or not certainly overlapping: the nearest pair, certified after the fact. Below: the
// gap on the witnesses' direction when positive (then they are apart) and, on every axis, the
// signed distance is at least minus its overlap. Where they may overlap, a witness may lie in
// the other shape by up to the depth, which joins the witnesses' bound.
Separation closest(const Triangle& t, const Relative& w, const Obb& box, const Axes& axes, const Bound& bound) {
  double gap = 0;
  const NearestPair best = nearest_features(t, w, box, bound, gap);
  const double least = axes.least_depth();
  double lower = -(least + bound.evaluation());
  if (gap > 0) lower = std::max(lower, gap);
  return Separation::certified(best.on_a, best.on_b, bound.point() + std::max(0.0, least + bound.evaluation()), lower);
}

template <class Records>
Separation triangle_obb(const Triangle& t, const Obb& box, Records& records) {
  if (!finite(t) || !in_domain(box)) return Separation::outside_the_domain();
  const Relative w{t.v[0] - box.center, t.v[1] - box.center, t.v[2] - box.center};
  const double reach = std::max({norm1(w[0]), norm1(w[1]), norm1(w[2])});
  const double magnitude = std::max({max_abs(t.v[0]), max_abs(t.v[1]), max_abs(t.v[2]), max_abs(box.center)});
  const Bound bound{(reach + norm1(box.half)) * (1 + 8 * fp::u), magnitude};
  const Axes axes = measure_axes(t, w, box, bound);
  const double lower = axes.certain_depth(bound.evaluation());
  const Separation s = lower > 0 ? depth(t, w, box, axes, lower, bound) : closest(t, w, box, axes, bound);
  records.add(bounds::TriangleBoxSeparation{t, box, s, bound});
  return s;
}

}  // namespace

Separation distance_triangle_obb(const Triangle& t, const Obb& box) {
  bounds::NoRecords none;
  return triangle_obb(t, box, none);
}

Separation distance_triangle_obb(const Triangle& t, const Obb& box, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return triangle_obb(t, box, into);
}

}  // namespace cc
