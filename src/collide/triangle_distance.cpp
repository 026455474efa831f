#include "collide/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide/fp.h"
#include "collide/length.h"
#include "collide/segment_distance.h"

namespace cc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The best candidate pair so far: a point of a, a point of b, and their squared distance as
// computed on the differences scaled by 2^-exponent (the pair's extent brought near 1, so the
// squares neither overflow nor, but for pairs far nearer than the extent, underflow). Only the
// choice depends on it: the bound is certified for whichever pair is chosen.
struct Best {
  int exponent = 0;
  Vec3 on_a, on_b;
  double square = kInf;

  /// Whether the pair is kept (nearer than every one before it).
  bool keep_nearer(const Vec3& a, const Vec3& b) {
    const Vec3 d = scaled(b - a, exponent);
    const double sq = dot(d, d);
    if (!(sq < square)) return false;
    on_a = a, on_b = b, square = sq;
    return true;
  }
};

// A triangle's normal, scaled (a direction only); zero for a degenerate triangle.
Vec3 normal_of(const Triangle& t) { return unit_scaled(cross(t.v[1] - t.v[0], t.v[2] - t.v[0])); }

// The foot of p on the plane of t (n its normal_of), when it lies in t (t not degenerate): p's
// nearest point of t is then the foot, else on t's edges.
bool foot_in(const Vec3& p, const Triangle& t, const Vec3& n, Vec3& foot) {
  const double nn = dot(n, n);
  if (!(nn > 0)) return false;
  foot = p - (dot(p - t.v[0], n) / nn) * n;
  for (int i = 0; i < 3; ++i) {
    const Vec3& from = t.v[i];
    const Vec3& to = t.v[(i + 1) % 3];
    if (dot(cross(to - from, foot - from), n) < 0) return false;
  }
  return true;
}

// Where the segment from p to q crosses the plane of t inside t, if it does (t not degenerate,
// the segment not in the plane).
bool crossing(const Vec3& p, const Vec3& q, const Triangle& t, const Vec3& n, Vec3& at) {
  if (!(dot(n, n) > 0)) return false;
  const double dp = dot(p - t.v[0], n), dq = dot(q - t.v[0], n);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  const double s = std::clamp(dp / (dp - dq), 0.0, 1.0);
  at = p + s * (q - p);
  for (int i = 0; i < 3; ++i) {
    const Vec3& from = t.v[i];
    const Vec3& to = t.v[(i + 1) % 3];
    if (dot(cross(to - from, at - from), n) < 0) return false;
  }
  return true;
}

// The candidates for a closest pair with a point of `from` taken alone: its vertices' feet on
// `to` and its edges' crossings of `to`. `swapped`: `from` is b.
void vertices_and_crossings(const Triangle& from, const Triangle& to, bool swapped, Best& best) {
  const auto keep = [&](const Vec3& on_from, const Vec3& on_to) {
    swapped ? best.keep_nearer(on_to, on_from) : best.keep_nearer(on_from, on_to);
  };
  const Vec3 n = normal_of(to);
  if (!(dot(n, n) > 0)) return;  // degenerate: its edges' pairs are its candidates
  for (int i = 0; i < 3; ++i) {
    Vec3 foot;
    if (foot_in(from.v[i], to, n, foot)) keep(from.v[i], foot);
    // A crossing is on from's edge, and (nearly) in `to`: paired with its foot there. Where the
    // edge is nearly parallel to the plane the crossing is ill-conditioned, but the pair is
    // still a point of each triangle, merely not the closest; the edges' pairs cover that case.
    Vec3 at, on_to;
    if (crossing(from.v[i], from.v[(i + 1) % 3], to, n, at) && foot_in(at, to, n, on_to)) keep(at, on_to);
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
  // As segment_gap_along (segment_distance.cpp), over three vertices a side, measured from
  // a.v[0]: each side's extreme is one of three dots (4u m R each over the length), the rest as
  // there: 17.2u R, R the largest offset's 1-norm.
  const Vec3 unit = unit_scaled(direction);
  const double scale = length(unit);
  if (!(scale > 0) || !std::isfinite(scale)) return 0;
  double reach = 0, high_a = -kInf, low_b = kInf;
  for (int i = 0; i < 3; ++i) {
    const Vec3 ea = a.v[i] - a.v[0], eb = b.v[i] - a.v[0];
    reach = std::max({reach, norm1(ea), norm1(eb)});
    high_a = std::max(high_a, dot(unit, ea));
    low_b = std::min(low_b, dot(unit, eb));
  }
  return std::max(0.0, (low_b - high_a) / scale - 24 * fp::u * reach - fp::subnormal_slack);
}

Separation distance_triangle_triangle(const Triangle& a, const Triangle& b) {
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
      proven = best.keep_nearer(on_a, on_b) && separates(a, b, on_a, on_b);
    }
  }
  if (!proven) {
    vertices_and_crossings(a, b, false, best);
    vertices_and_crossings(b, a, true, best);
  }
  // Each witness: an edge's point (segment_distance.h, 16u of the largest coordinate M), a foot
  // p - (p - v0).n / n.n n (the difference u of 2M, the dot and quotient 5u, the product and
  // difference 2u of 2M: within 20uM per coordinate of a point in the plane, and the sign tests
  // let it stray from t by the rounding of its own edges' products, a few u of M), or a
  // crossing (as a segment's point): 32u M in length.
  double magnitude = 0;
  for (int i = 0; i < 3; ++i) magnitude = std::max({magnitude, max_abs(a.v[i]), max_abs(b.v[i])});
  const double point_error = 32 * fp::u * magnitude + fp::subnormal_slack;
  const double d = length(best.on_b - best.on_a);
  const double upper = d + 2 * point_error + 4 * fp::u * d;
  const double lower = d > 0 ? triangle_gap_along(a, b, best.on_b - best.on_a) : 0;
  return {d, best.on_a, best.on_b, std::max(upper - d, d - lower), point_error};
}

}  // namespace cc
