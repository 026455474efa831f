#include "collide/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide/fp.h"
#include "collide/length.h"
#include "collide/projection_gap.h"
#include "collide/record_sink.h"
#include "collide/segment_distance.h"
#include "collide/triangle_distance_bound.h"
#include "collide/triangle_foot.h"

namespace cc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The best candidate pair so far: a point of a, a point of b, the normal of the features they
// lie on (an edge pair's cross product, a face's normal: the direction a closest pair of those
// features takes, free of the witnesses' rounding), and their squared distance as computed on
// the differences scaled by 2^-exponent (the pair's extent brought near 1, so the squares
// neither overflow nor, but for pairs far nearer than the extent, underflow). Only the choice
// depends on it: the bound is certified for whichever pair is chosen.
struct Best {
  int exponent = 0;
  Vec3 on_a, on_b, normal;
  double square = kInf;

  /// Whether the pair is kept (nearer than every one before it).
  bool keep_nearer(const Vec3& a, const Vec3& b, const Vec3& features_normal) {
    const Vec3 d = scaled(b - a, exponent);
    const double sq = dot(d, d);
    if (!(sq < square)) return false;
    on_a = a, on_b = b, normal = features_normal, square = sq;
    return true;
  }
};

// A triangle's normal, scaled (a direction only); zero for a degenerate triangle.
Vec3 normal_of(const Triangle& t) { return unit_scaled(cross(t.v[1] - t.v[0], t.v[2] - t.v[0])); }

// A point of the segment from p to q near where it crosses the plane of t (n its normal_of),
// if its ends lie on both sides of the plane or on it (and not both on it).
bool crossing(const Vec3& p, const Vec3& q, const Vec3& v0, const Vec3& n, Vec3& at) {
  const double dp = dot(p - v0, n), dq = dot(q - v0, n);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  at = p + std::clamp(dp / (dp - dq), 0.0, 1.0) * (q - p);
  return true;
}

// The candidates for a closest pair with a point of `from` taken alone: its vertices' feet on
// `to` and its edges' crossings of `to`, each crossing paired with its foot there. Where an edge
// is nearly parallel to the plane its crossing is ill-conditioned, but the pair is still a point
// of each triangle, merely not the closest; the edges' pairs cover that case. `swapped`: `from`
// is b.
void vertices_and_crossings(const Triangle& from, const Triangle& to, bool swapped, Best& best) {
  const Vec3 n = normal_of(to);
  if (!(dot(n, n) > 0)) return;  // degenerate: its edges' pairs are its candidates
  const auto keep = [&](const Vec3& on_from, const Vec3& on_to) {
    if (swapped) {
      best.keep_nearer(on_to, on_from, n);
    } else {
      best.keep_nearer(on_from, on_to, n);
    }
  };
  for (int i = 0; i < 3; ++i) {
    Vec3 at, on_to;
    if (foot_in_triangle(from.v[i], to, on_to)) keep(from.v[i], on_to);
    if (crossing(from.v[i], from.v[(i + 1) % 3], to.v[0], n, at) && foot_in_triangle(at, to, on_to)) keep(at, on_to);
  }
}

// Whether the direction from on_a to on_b separates the triangles with on_a and on_b at their
// extremes: every vertex of a no further along it than on_a, every vertex of b no nearer than
// on_b (as computed). Then the pair is a closest one (the gap along that direction is their
// distance), and the other candidates need not be tried; the bound is certified either way.
bool separates(const Triangle& a, const Triangle& b, const Vec3& on_a, const Vec3& on_b) {
  const Vec3 v = unit_scaled(on_b - on_a);  // a direction only: its products neither overflow nor underflow
  if (v == Vec3{}) return false;
  for (int k = 0; k < 3; ++k) {
    if (dot(v, a.v[k] - on_a) > 0 || dot(v, b.v[k] - on_b) < 0) return false;
  }
  return true;
}

}  // namespace

double triangle_gap_along(const Triangle& a, const Triangle& b, const Vec3& direction) {
  return projection_gap(a.v, b.v, direction);
}

namespace {

template <class Records>
Separation triangle_triangle(const Triangle& a, const Triangle& b, Records& records) {
  if (!finite(a) || !finite(b)) return Separation::outside_the_domain();
  Best best;
  double extent = 0;
  for (int i = 0; i < 3; ++i) extent = std::max({extent, max_abs(a.v[i] - a.v[0]), max_abs(b.v[i] - a.v[0])});
  best.exponent = extent > 0 ? fp::exponent_of(extent) : 0;
  bool proven = false;  // an edge pair whose direction separates the triangles: closest, done
  for (int i = 0; i < 3 && !proven; ++i) {
    const Segment ea{a.v[i], a.v[(i + 1) % 3]};
    for (int j = 0; j < 3 && !proven; ++j) {
      const Segment eb{b.v[j], b.v[(j + 1) % 3]};
      const auto [s, t] = closest_segment_parameters(ea, eb);
      const Vec3 on_a = ea.a + s * (ea.b - ea.a), on_b = eb.a + t * (eb.b - eb.a);
      // A proven pair is a closest one, so nearer than any before it: only a kept pair is tried.
      proven = best.keep_nearer(on_a, on_b, unit_scaled(cross(ea.b - ea.a, eb.b - eb.a))) &&
               separates(a, b, on_a, on_b);
    }
  }
  if (!proven) {
    vertices_and_crossings(a, b, false, best);
    vertices_and_crossings(b, a, true, best);
  }
  // The witnesses' bound: triangle_distance_bound.h.
  double magnitude = 0;
  for (int i = 0; i < 3; ++i) magnitude = std::max({magnitude, max_abs(a.v[i]), max_abs(b.v[i])});
  const bounds::TriangleDistanceBound bound{magnitude};
  // The lower end: the gap along the witnesses' direction, and along their features' normal,
  // which a noisy pair of witnesses (nearly touching triangles, where their rounding turns
  // their direction) does not tilt. Both face from a to b; none when the witnesses meet.
  const Vec3 along = best.on_b - best.on_a;
  double lower = 0;
  if (along != Vec3{}) {
    const Vec3 normal = dot(best.normal, along) < 0 ? -1.0 * best.normal : best.normal;
    lower = std::max(triangle_gap_along(a, b, along), triangle_gap_along(a, b, normal));
  }
  const Separation s = Separation::certified(best.on_a, best.on_b, bound.point(), lower);
  records.add(bounds::TriangleSeparation{a, b, s, bound});
  return s;
}

}  // namespace

Separation distance_triangle_triangle(const Triangle& a, const Triangle& b) {
  bounds::NoRecords none;
  return triangle_triangle(a, b, none);
}

Separation distance_triangle_triangle(const Triangle& a, const Triangle& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return triangle_triangle(a, b, into);
}

}  // namespace cc
