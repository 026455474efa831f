#include "collide/obb_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "collide/length.h"
#include "collide/obb_distance_bound.h"
#include "collide/obb_fit.h"
#include "collide/record_sink.h"
#include "collide/segment.h"
#include "collide/segment_distance.h"
#include "collide/triangle.h"
#include "collide/triangle_distance.h"

namespace cc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool in_domain(const Obb& b) {
  return finite(b.center) && finite(b.half) && finite(b.axes) && b.half.x >= 0 && b.half.y >= 0 && b.half.z >= 0;
}

// The radius of a box's projection on n: sum_k half_k |axis_k . n| (exact for the parallelepiped).
double radius_along(const Obb& box, const Vec3& n) {
  return fp::sum3(box.half.x * std::fabs(dot(box.axes.col[0], n)), box.half.y * std::fabs(dot(box.axes.col[1], n)),
                  box.half.z * std::fabs(dot(box.axes.col[2], n)));
}

// The overlap of the boxes' projections on `direction` over its length (d = b.center -
// a.center): > 0 overlapping by that much, < 0 apart by that much; +infinity for a zero direction
// (no information). Within ObbDistanceBound::evaluation() of the exact overlap on the computed
// direction.
double overlap_along(const Obb& a, const Obb& b, const Vec3& d, const Vec3& direction) {
  const Vec3 n = unit_scaled(direction);  // |n| in [1, 2 sqrt 3]: no underflow, no overflow
  const double n_length = length(n);
  if (!(n_length > 0)) return kInf;
  return ((radius_along(a, n) + radius_along(b, n)) - std::fabs(dot(d, n))) / n_length;
}

// a d - b c within 2 ulps (Kahan's difference of products: b c's rounding error, exact by a fused
// multiply-add, put back), and exactly 0 when it is 0; but for underflow.
double difference_of_products(double a, double d, double b, double c) {
  const double w = b * c;
  const double e = std::fma(-b, c, w);
  const double f = std::fma(a, d, -w);
  return f + e;
}

// a x b, each component within 2 ulps of the exact one however nearly parallel a and b are (the
// plain cross product errs by u of the products, which is all of it for nearly parallel edges);
// b x a is its exact negation.
Vec3 accurate_cross(const Vec3& a, const Vec3& b) {
  if (lexicographic_less(b, a)) return -accurate_cross(b, a);
  return {difference_of_products(a.y, b.z, a.z, b.y), difference_of_products(a.z, b.x, a.x, b.z),
          difference_of_products(a.x, b.y, a.y, b.x)};
}

// A candidate axis: a box's axis or an edge pair's cross product, the overlap on it, and how far
// that overlap may lie from the overlap on the exact face normal of a - b it stands for.
struct Axis {
  Vec3 n;
  double depth = kInf;
  double direction_error = 0;
  double angle_error = 0;  // of its unit direction
};

// The axes a depth is measured on, and the widest sliver left out (ObbDistanceBound::sliver).
struct Axes {
  std::array<Axis, 15> axis;
  int count = 0;
  double sliver = 0;
  int least = -1;  // the axis of least depth
};

// The overlap on each axis from `first` on, and the least so far.
void measure(const Obb& a, const Obb& b, const Vec3& d, int first, Axes& axes) {
  for (int k = first; k < axes.count; ++k) {
    Axis& x = axes.axis[k];
    x.depth = overlap_along(a, b, d, x.n);
    if (axes.least < 0 || x.depth < axes.axis[axes.least].depth) axes.least = k;
  }
}

// The faces' axes, then, unless one of them shows the boxes apart for certain (then the closest
// pair needs no more), the edge pairs'.
Axes measure_axes(const Obb& a, const Obb& b, const Vec3& d, const bounds::ObbDistanceBound& bound) {
  Axes axes;
  const double face_angle = 8 * kObbOrthonormalTolerance;
  for (int k = 0; k < 3; ++k) {
    axes.axis[axes.count++] = {a.axes.col[k], 0, bound.face_direction(), face_angle};
    axes.axis[axes.count++] = {b.axes.col[k], 0, bound.face_direction(), face_angle};
  }
  measure(a, b, d, 0, axes);
  if (axes.axis[axes.least].depth + bound.evaluation() < 0) return axes;
  const int faces = axes.count;
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
      axes.axis[axes.count++] = {c, 0, bound.cross_direction(c_length), bounds::ObbDistanceBound::cross_angle(c_length)};
    }
  }
  measure(a, b, d, faces, axes);
  return axes;
}

// The face, edge or corner of `box` farthest along the unit direction n, every axis within
// `tolerance` of perpendicular to n taken whole (the largest never), as triangles of its corners
// (corners(box), obb_fit.h: bit k of an index set for +half_k; two for a face, one degenerate
// otherwise) moved by `shift`. Returns how many.
int farthest_feature(const Obb& box, const Vec3& n, double tolerance, const Vec3& shift, Triangle out[2]) {
  const std::array<Vec3, 8> corner = corners(box);
  int bits = 0, free[3], free_count = 0, largest = 0;
  double along[3];
  for (int k = 0; k < 3; ++k) {
    along[k] = dot(box.axes.col[k], n);
    if (std::fabs(along[k]) > std::fabs(along[largest])) largest = k;
  }
  for (int k = 0; k < 3; ++k) {
    if (k != largest && std::fabs(along[k]) <= tolerance) {
      free[free_count++] = k;
    } else if (along[k] > 0) {
      bits |= 1 << k;
    }
  }
  const auto at = [&](int extra) { return corner[bits | extra] + shift; };
  if (free_count == 0) {
    const Vec3 p = at(0);
    out[0] = {{p, p, p}};
    return 1;
  }
  const int e1 = 1 << free[0];
  if (free_count == 1) {
    const Vec3 p = at(0), q = at(e1);
    out[0] = {{p, q, q}};
    return 1;
  }
  const int e2 = 1 << free[1];
  const Vec3 p00 = at(0), p10 = at(e1), p11 = at(e1 | e2), p01 = at(e2);
  out[0] = {{p00, p10, p11}};
  out[1] = {{p00, p11, p01}};
  return 2;
}

// Overlapping for certain: minus the least depth, the witnesses the nearest pair of a's feature
// farthest along the least axis and b's nearest along it, moved out by the depth.
Separation depth(const Obb& a, const Obb& b, const Vec3& d, const Axes& axes, double lower,
                 const bounds::ObbDistanceBound& bound) {
  const Axis& least = axes.axis[axes.least];
  LengthAndDirection ld = length_and_direction(unit_scaled(least.n));
  Vec3 n = ld.direction;
  if (dot(d, n) < 0) n = -n;  // b is pushed along +n
  const double m = least.depth;
  const Vec3 shift = m * n;
  const double tolerance = 16 * fp::u + least.angle_error;
  Triangle on_a[2], on_b[2];
  const int na = farthest_feature(a, n, tolerance, {}, on_a);
  const int nb = farthest_feature(b, -n, tolerance, shift, on_b);
  Separation nearest;
  nearest.distance = kInf;
  for (int i = 0; i < na; ++i) {
    for (int j = 0; j < nb; ++j) {
      const Separation s = distance_triangle_triangle(on_a[i], on_b[j]);
      if (s.distance < nearest.distance) nearest = s;
    }
  }
  // The pair meets where the least axis is a face of a - b; its gap counts in the witnesses'
  // bound, so that they are as far apart as the depth says within it.
  const double gap = nearest.distance;
  return {-m, nearest.on_a, nearest.on_b - shift, std::max(bound.evaluation(), m - lower),
          fp::sum3(bound.point(), gap / 2, 2 * fp::u * m)};
}

// A pair of points and their squared distance, on differences scaled by 2^-exponent.
struct Nearest {
  int exponent = 0;
  Vec3 on_a, on_b;
  double square = kInf;
  void keep_nearer(const Vec3& p, const Vec3& q) {
    const Vec3 v = scaled(q - p, exponent);
    const double sq = dot(v, v);
    if (sq < square) on_a = p, on_b = q, square = sq;
  }
};

// The box's coordinates of p (its axes' components, transposed).
Vec3 local(const Obb& box, const Vec3& p) { return transpose_times(box.axes, p - box.center); }

// The point of the box at the coordinates clamped to it.
Vec3 clamped(const Obb& box, const Vec3& q) {
  const Vec3 c{std::clamp(q.x, -box.half.x, box.half.x), std::clamp(q.y, -box.half.y, box.half.y),
               std::clamp(q.z, -box.half.z, box.half.z)};
  return box.center + box.axes * c;
}

// A lower bound (scaled, squared) on the distance from the segment between the box coordinates
// p and q to the box: each axis's gap is at most that of every point of the segment. Only
// chooses which edges are tried.
double square_gap_to_box(const Obb& box, const Vec3& p, const Vec3& q, int exponent) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double g = std::max({0.0, std::min(p[k], q[k]) - box.half[k], -box.half[k] - std::max(p[k], q[k])});
    const double s = fp::scale2(g, -exponent);
    sum += s * s;
  }
  return sum;
}

// The nearest of each corner against the other box and of each pair of edges whose segments are
// not farther from the other box than the best corner's pair.
Nearest nearest_features(const Obb& a, const Obb& b, int exponent) {
  const std::array<Vec3, 8> ca = corners(a), cb = corners(b);
  std::array<Vec3, 8> la, lb;  // the corners' coordinates in the other box
  Nearest best;
  best.exponent = exponent;
  for (int i = 0; i < 8; ++i) {
    la[i] = local(b, ca[i]), lb[i] = local(a, cb[i]);
    best.keep_nearer(ca[i], clamped(b, la[i]));
    best.keep_nearer(clamped(a, lb[i]), cb[i]);
  }
  // Edge k of a box joins corner i (bit k clear) and i | 1 << k.
  struct Edge {
    int from, to;
  };
  std::array<Edge, 12> ea, eb;
  int na = 0, nb = 0;
  const double keep_below = best.square * (1 + 0x1p-20);
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 8; ++i) {
      if (i >> k & 1) continue;
      const int j = i | 1 << k;
      if (square_gap_to_box(b, la[i], la[j], exponent) <= keep_below) ea[na++] = {i, j};
      if (square_gap_to_box(a, lb[i], lb[j], exponent) <= keep_below) eb[nb++] = {i, j};
    }
  }
  for (int i = 0; i < na; ++i) {
    const Segment sa{ca[ea[i].from], ca[ea[i].to]};
    for (int j = 0; j < nb; ++j) {
      const Segment sb{cb[eb[j].from], cb[eb[j].to]};
      const auto [s, t] = closest_segment_parameters(sa, sb);
      best.keep_nearer(sa.a + s * (sa.b - sa.a), sb.a + t * (sb.b - sb.a));
    }
  }
  return best;
}

// Apart, or not certainly overlapping: the nearest pair, certified after the fact. Below: the
// gap on the witnesses' direction when positive (then they are apart) and, on every axis, the
// signed distance is at least minus its overlap. Where they may overlap, a witness may lie in
// the other box by up to the depth, which joins the witnesses' bound.
Separation closest(const Obb& a, const Obb& b, const Vec3& d, const Axes& axes, const bounds::ObbDistanceBound& bound) {
  const Nearest best = nearest_features(a, b, bound.size > 0 ? fp::exponent_of(bound.size) : 0);
  const double least = axes.least >= 0 ? axes.axis[axes.least].depth : kInf;
  double lower = -(least + bound.evaluation());
  const Vec3 along = best.on_b - best.on_a;
  if (along != Vec3{}) {
    const double gap = -overlap_along(a, b, d, along) - bound.evaluation();
    if (gap > 0) lower = std::max(lower, gap);
  }
  return Separation::certified(best.on_a, best.on_b, bound.point() + std::max(0.0, least + bound.evaluation()), lower);
}

template <class Records>
Separation obb_obb(const Obb& a, const Obb& b, Records& records) {
  if (!in_domain(a) || !in_domain(b)) return Separation::outside_the_domain();
  const Vec3 d = b.center - a.center;
  const bounds::ObbDistanceBound bound{fp::sum3(norm1(d), norm1(a.half), norm1(b.half)) * (1 + 8 * fp::u),
                                       std::max(max_abs(a.center), max_abs(b.center))};
  const Axes axes = measure_axes(a, b, d, bound);
  // Every face normal of a - b measured is at least this deep, every one left out at least this
  // less its sliver: overlapping for certain when it is positive.
  double lower = kInf;
  for (int k = 0; k < axes.count; ++k) {
    const Axis& x = axes.axis[k];
    lower = std::min(lower, x.depth - bound.evaluation() - x.direction_error);
  }
  lower -= axes.sliver;
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
