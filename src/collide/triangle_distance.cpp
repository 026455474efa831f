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

namespace cc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr int next(int i) { return i == 2 ? 0 : i + 1; }
constexpr int other(int i) { return i == 0 ? 2 : i - 1; }  // the vertex off edge i

Vec3 min(const Vec3& p, const Vec3& q) { return {std::min(p.x, q.x), std::min(p.y, q.y), std::min(p.z, q.z)}; }
Vec3 max(const Vec3& p, const Vec3& q) { return {std::max(p.x, q.x), std::max(p.y, q.y), std::max(p.z, q.z)}; }

// Dot products here sum left to right (dot_in_order): they choose the witnesses only, whose
// bounds do not depend on the choice, where fp::sum3's symmetry buys nothing.

// Where a witness lies on its triangle, in the forms its bound is derived for
// (triangle_distance_bound.h): on edge `edge`, v[edge] + s (v[edge + 1] - v[edge]) with s in
// [0, 1]; on the face (edge < 0), v0 + s e1 + t e2 with s, t >= 0 and s + t <= 1 as computed.
struct Place {
  int edge = 0;
  double s = 0, t = 0;

  Vec3 on(const Triangle& tri) const {
    if (edge >= 0) return tri.v[edge] + s * (tri.v[next(edge)] - tri.v[edge]);
    return tri.v[0] + s * (tri.v[1] - tri.v[0]) + t * (tri.v[2] - tri.v[0]);
  }
};

// A triangle as the choice of witnesses sees it, in a frame shared with the other: its vertices
// less the first triangle's first vertex and its edges (differences of its own vertices, so
// that their directions are as accurate as the triangle's), both scaled by one power of two
// that brings the pair's extent into [1, 2). Products of four neither overflow nor, but for
// features far smaller than the pair, underflow; only the choice of witnesses depends on these.
struct Local {
  Vec3 v[3], e[3];      // e[i] = v[i + 1] - v[i]
  double length2[3]{};  // e[i] . e[i]
  Vec3 n;               // e1 x e2 (e1 = v1 - v0, e2 = v2 - v0)
  bool face = false;    // n is long enough for face coordinates
  bool well_shaped = false;  // and its direction accurate (sin of the angle at v0 above 2^-8)
  Vec3 gs, gt;          // w . gs, w . gt: the face coordinates (s, t) of v0 + w

  // `offsets`: t's vertices less the origin; `factor`: 2^-exponent, or 0 where that is not a
  // normal double (then each value is scaled apart).
  Local(const Triangle& t, const Vec3 offsets[3], double factor, int exponent) {
    const auto scale = [&](const Vec3& x) { return factor != 0 ? factor * x : scaled(x, exponent); };
    for (int i = 0; i < 3; ++i) {
      v[i] = scale(offsets[i]), e[i] = scale(t.v[next(i)] - t.v[i]);
      length2[i] = dot_in_order(e[i], e[i]);
    }
    const Vec3 e2 = -e[2];
    n = cross(e[0], e2);
    const double nn = dot_in_order(n, n);
    // w = s e1 + t e2 + h n: (e2 x n) . e1 = n . n and (e2 x n) . e2 = 0 give s, (n x e1) the same
    // for t. Below 2^-1000 (a sliver far thinner than the pair), the triangle is taken as its edges.
    face = nn >= 0x1p-1000;
    if (!face) return;
    well_shaped = nn > 0x1p-16 * length2[0] * length2[2];
    const double inverse = 1 / nn;
    gs = inverse * cross(e2, n), gt = inverse * cross(n, e[0]);
  }

  // The face coordinates of local point x, when they put its foot on the face.
  bool foot(const Vec3& x, Place& at) const {
    const Vec3 w = x - v[0];
    const double s = dot_in_order(w, gs), t = dot_in_order(w, gt);
    if (!(s >= 0 && t >= 0 && s + t <= 1)) return false;
    at = {-1, s, t};
    return true;
  }
  // The local point at a place.
  Vec3 at(const Place& p) const {
    if (p.edge >= 0) return v[p.edge] + p.s * e[p.edge];
    return v[0] + p.s * e[0] - p.t * e[2];
  }
};

// The nearest candidate pair so far: where its witnesses lie, which features' normal certifies
// it (3i + j for edges i of a and j of b, -1 a's face, -2 b's face) and its squared local
// distance.
struct Choice {
  Place on_a, on_b;
  int features = 0;
  double square = kInf;
};

// The search for the witnesses. `meets`: the squared local distance below which a pair is taken
// at once (nothing nearer by more than the witnesses' own rounding can be found).
struct Search {
  const Local& a;
  const Local& b;
  double meets;
  Choice best;

  // Keeps the pair when nearer than every one before it; whether it is kept.
  bool keep(const Place& on_a, const Place& on_b, int features) {
    const Vec3 d = b.at(on_b) - a.at(on_a);
    const double sq = dot_in_order(d, d);
    if (!(sq < best.square)) return false;
    best = {on_a, on_b, features, sq};
    return true;
  }

  // The vertex of `from` nearest the plane of `face` (h: the heights of from's vertices along
  // face.n), when `from` lies wholly on one side of that plane and the vertex's foot on the face:
  // then the vertex and its foot are a closest pair. Only for a face whose normal is accurate.
  static bool vertex_over_face(const Local& face, const Local& from, const double h[3], Place& on_face, int& vertex) {
    if (!face.well_shaped) return false;
    const bool above = h[0] > 0 && h[1] > 0 && h[2] > 0, below = h[0] < 0 && h[1] < 0 && h[2] < 0;
    if (!above && !below) return false;
    vertex = 0;
    for (int k = 1; k < 3; ++k) {
      if (std::fabs(h[k]) < std::fabs(h[vertex])) vertex = k;
    }
    return face.foot(from.v[vertex], on_face);
  }

  // Every vertex of `from` over the face of `to`, kept where its foot lies on the face.
  void vertices(const Local& from, const Local& to, bool from_b) {
    if (!to.face) return;
    for (int k = 0; k < 3; ++k) {
      Place foot;
      if (!to.foot(from.v[k], foot)) continue;
      const Place vertex{k, 0, 0};
      if (from_b) {
        keep(foot, vertex, -1);
      } else {
        keep(vertex, foot, -2);
      }
    }
  }

  // The edges of `from` through the plane of `to` (h: the heights of from's vertices along
  // to.n), each crossing paired with its foot on `to` where that lies on the face. Where an edge
  // is nearly parallel to the plane its crossing is ill-conditioned, but the pair is still a
  // point of each triangle, merely not the closest; the edges' pairs cover that case. Whether
  // a kept pair meets.
  bool crossings(const Local& from, const Local& to, const double h[3], bool from_b) {
    if (!to.face) return false;
    for (int k = 0; k < 3; ++k) {
      const double hp = h[k], hq = h[next(k)];
      if ((hp > 0 && hq > 0) || (hp < 0 && hq < 0) || hp == hq) continue;
      const double r = std::clamp(hp / (hp - hq), 0.0, 1.0);
      const Place crossing{k, r, 0};
      Place foot;
      if (!to.foot(from.at(crossing), foot)) continue;
      if (from_b ? keep(foot, crossing, -1) : keep(crossing, foot, -2)) {
        if (best.square <= meets) return true;
      }
    }
    return false;
  }

  // The edge pairs: first that of the edges whose midpoints are nearest (first_edge_pair), then
  // the others (other_edge_pairs) but for edges whose bounding boxes lie no nearer than the
  // nearest pair so far (they hold no nearer pair, up to the boxes' rounding). Each returns
  // whether a pair is proven closest: it meets, or its direction separates the triangles with it
  // at their extremes (the vertex off each edge no further along it than its witness on a, no
  // nearer than its witness on b; the edges themselves lie so, their witnesses being their
  // closest pair).
  int first = 0;  // the pair with the nearest midpoints, 3i + j
  bool first_edge_pair() {
    double nearest = kInf;
    for (int k = 0; k < 9; ++k) {
      const int i = k / 3, j = k % 3;
      const Vec3 d = (b.v[j] + b.v[next(j)]) - (a.v[i] + a.v[next(i)]);
      const double sq = dot_in_order(d, d);
      if (sq < nearest) nearest = sq, first = k;
    }
    return edge_pair(first);
  }
  bool other_edge_pairs() {
    Vec3 lo_a[3], hi_a[3], lo_b[3], hi_b[3];
    for (int i = 0; i < 3; ++i) {
      lo_a[i] = min(a.v[i], a.v[next(i)]), hi_a[i] = max(a.v[i], a.v[next(i)]);
      lo_b[i] = min(b.v[i], b.v[next(i)]), hi_b[i] = max(b.v[i], b.v[next(i)]);
    }
    for (int k = 0; k < 9; ++k) {
      const int i = k / 3, j = k % 3;
      const Vec3 gap = max(max(lo_b[j] - hi_a[i], lo_a[i] - hi_b[j]), Vec3{});
      if (k != first && dot_in_order(gap, gap) < best.square && edge_pair(k)) return true;
    }
    return false;
  }

  // The closest pair of edges i = k / 3 of a and j = k % 3 of b, kept when nearer than every pair
  // before it; whether it is proven closest (first_edge_pair).
  bool edge_pair(int k) {
    const int i = k / 3, j = k % 3;
    const auto [s, t] = detail::closest_parameters(a.e[i], b.e[j], a.v[i] - b.v[j], a.length2[i], b.length2[j]);
    const Place on_a{i, s, 0}, on_b{j, t, 0};
    // A proven pair is a closest one, so nearer than any before it: only a kept pair is tried.
    if (!keep(on_a, on_b, k)) return false;
    if (best.square <= meets) return true;
    const Vec3 pa = a.at(on_a), pb = b.at(on_b), v = pb - pa;
    return dot_in_order(v, a.v[other(i)] - pa) <= 0 && dot_in_order(v, b.v[other(j)] - pb) >= 0;
  }
};

// Whether a triangle whose vertices lie at heights h over a plane reaches it or both its sides.
bool straddles(const double h[3]) { return !((h[0] > 0 && h[1] > 0 && h[2] > 0) || (h[0] < 0 && h[1] < 0 && h[2] < 0)); }

// The witnesses: proven closest where a test shows it, else the nearest of the candidates a
// closest pair is among (each vertex against the other triangle's face, each pair of edges, each
// edge's crossing of the other triangle). In order:
//  - each triangle through the other's plane (the heights of its vertices over it of both signs,
//    or 0), as where they meet: the crossings of edges through the other triangle; one whose
//    witnesses meet is taken;
//  - the edge pair with the nearest midpoints, taken where it meets or separates the triangles
//    with its witnesses at their extremes (most apart pairs end here);
//  - b wholly on one side of a's plane and its vertex nearest it over a's face (or the same with
//    a and b exchanged): that vertex and its foot, a closest pair;
//  - the other edge pairs, taken as the first;
//  - else the nearest of all the candidates.
Choice witnesses(const Local& a, const Local& b, double meets) {
  Search search{a, b, meets, {}, 0};
  double ha[3], hb[3];  // a's vertices over b's plane, b's over a's
  for (int k = 0; k < 3; ++k) hb[k] = dot_in_order(b.v[k] - a.v[0], a.n), ha[k] = dot_in_order(a.v[k] - b.v[0], b.n);
  const bool through = straddles(ha) && straddles(hb);
  if (through && (search.crossings(a, b, ha, false) || search.crossings(b, a, hb, true))) return search.best;
  if (search.first_edge_pair()) return search.best;
  Place foot;
  int vertex = 0;
  if (!through && Search::vertex_over_face(a, b, hb, foot, vertex)) return {foot, {vertex, 0, 0}, -1, 0};
  if (!through && Search::vertex_over_face(b, a, ha, foot, vertex)) return {{vertex, 0, 0}, foot, -2, 0};
  if (search.other_edge_pairs()) return search.best;
  search.vertices(a, b, false);
  search.vertices(b, a, true);
  if (!through) {
    search.crossings(a, b, ha, false);
    search.crossings(b, a, hb, true);
  }
  return search.best;
}

}  // namespace

double triangle_gap_along(const Triangle& a, const Triangle& b, const Vec3& direction) {
  return projection_gap(a.v, b.v, direction);
}

namespace {

template <class Records>
Separation triangle_triangle(const Triangle& a, const Triangle& b, Records& records) {
  if (!finite(a) || !finite(b)) return Separation::outside_the_domain();
  const Vec3 offsets_a[3] = {Vec3{}, a.v[1] - a.v[0], a.v[2] - a.v[0]};
  const Vec3 offsets_b[3] = {b.v[0] - a.v[0], b.v[1] - a.v[0], b.v[2] - a.v[0]};
  double extent = 0, magnitude = 0;
  for (int i = 0; i < 3; ++i) {
    extent = std::max(extent, std::max(max_abs(offsets_a[i]), max_abs(offsets_b[i])));
    magnitude = std::max(magnitude, std::max(max_abs(a.v[i]), max_abs(b.v[i])));
  }
  const int exponent = extent > 0 ? fp::exponent_of(extent) : 0;
  // 2^-exponent as one factor where it is a normal double, else 0 (scaled one value at a time).
  const double factor = exponent >= -1000 && exponent <= 1000 ? fp::scale2(1, -exponent) : 0;
  const Local la(a, offsets_a, factor, exponent), lb(b, offsets_b, factor, exponent);
  // The witnesses' bound: triangle_distance_bound.h. A pair nearer than half their rounding is
  // taken at once: the distance's bound is then twice theirs, whatever pair were chosen.
  const bounds::TriangleDistanceBound bound{magnitude};
  const double meets = fp::scale2(bound.point_rounding() / 2, -exponent);
  const Choice chosen = witnesses(la, lb, meets * meets);
  const Vec3 on_a = chosen.on_a.on(a), on_b = chosen.on_b.on(b);
  // The lower end: the gap along the witnesses' direction, and along their features' normal,
  // which a noisy pair of witnesses (nearly touching triangles, where their rounding turns their
  // direction) does not tilt. Both face from a to b; none when the witnesses meet. The normal is
  // tried first where it is a closest pair's direction (a face's foot, or an edge pair's
  // witnesses inside both edges), the witnesses' direction first elsewhere; the second only where
  // the first leaves the answer short.
  const auto lower = [&](const auto& enough) {
    const Vec3 along = on_b - on_a;
    if (along == Vec3{}) return 0.0;
    const int f = chosen.features;
    Vec3 normal = f == -1 ? la.n : f == -2 ? lb.n : cross(la.e[f / 3], lb.e[f % 3]);
    if (dot(normal, along) < 0) normal = -1.0 * normal;
    const bool interior = f < 0 || (chosen.on_a.s > 0 && chosen.on_a.s < 1 && chosen.on_b.s > 0 && chosen.on_b.s < 1);
    const Vec3& first = interior ? normal : along;
    const double gap = triangle_gap_along(a, b, first);
    return enough(gap) ? gap : std::max(gap, triangle_gap_along(a, b, interior ? along : normal));
  };
  const Separation s = Separation::certified_lazily(on_a, on_b, bound.point(), lower);
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
