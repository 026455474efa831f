#include "collide/triangle_intersection.h"

#include <algorithm>
#include <cmath>

#include "collide/exact_orientation.h"
#include "collide/triangle_triangle.h"

namespace cc {
namespace {

// A triangle as the point set it is: its vertices in order (3), a segment's ends in
// lexicographic order (2), or a point (1). A triangle keeps a projection one-to-one on its plane
// (`drop`, the axis dropped: where its normal's component is exactly nonzero, the largest one in
// floating point when that is) and the sign of its turn there.
struct Shape {
  std::array<Vec3, 3> v{};
  int n = 0;
  int drop = 2;
  int turn = 0;
};

// The signs below are of finite inputs, which exact_orientation.h always decides.
int orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return *orientation_sign(a, b, c, d); }
int orient2(const Vec3& a, const Vec3& b, const Vec3& c, int drop) { return *planar_orientation_sign(a, b, c, drop); }

// The axis of the largest component of (b - a) x (c - a) in floating point: the exact sign of
// that component is nonzero for nearly every triangle, so one sign decides it is not collinear.
int largest_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 m = abs(cross(b - a, c - a));
  return m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  const int k = largest_axis(a, b, c);
  return orient2(a, b, c, k) == 0 && orient2(a, b, c, (k + 1) % 3) == 0 && orient2(a, b, c, (k + 2) % 3) == 0;
}

Shape shape_of(const Triangle& t) {
  const int k = largest_axis(t.v[0], t.v[1], t.v[2]);
  for (int drop : {k, (k + 1) % 3, (k + 2) % 3}) {
    if (const int turn = orient2(t.v[0], t.v[1], t.v[2], drop); turn != 0) return {t.v, 3, drop, turn};
  }
  // Along a line the lexicographic order is the order of the points: its extremes are the ends.
  const auto [lo, hi] = std::minmax_element(t.v.begin(), t.v.end(), lexicographic_less);
  if (*lo == *hi) return {{*lo}, 1};
  return {{*lo, *hi}, 2};
}

// The kept coordinates of a projection dropping axis `drop`, in planar_orientation_sign's order.
int first_kept(int drop) { return (drop + 1) % 3; }
int second_kept(int drop) { return (drop + 2) % 3; }

// Whether p lies in the closed shape s, for p in the plane of s (a triangle: `drop` is one-to-one
// on that plane) or anywhere (a point, a segment: tested in 3-D).
bool contains(const Shape& s, const Vec3& p, int drop) {
  if (s.n == 1) return p == s.v[0];
  if (s.n == 2) return collinear(s.v[0], s.v[1], p) && !lexicographic_less(p, s.v[0]) && !lexicographic_less(s.v[1], p);
  const int turn = drop == s.drop ? s.turn : orient2(s.v[0], s.v[1], s.v[2], drop);
  for (int i = 0; i < 3; ++i) {
    if (orient2(s.v[i], s.v[(i + 1) % 3], p, drop) * turn < 0) return false;
  }
  return true;
}

// Whether the segment pq, whose ends lie strictly on either side of the plane of triangle t,
// crosses the closed t: the three edges of t pass around the line pq the same way, or touch it.
// Where the line touches two edges it passes through their common vertex: `vertex` names it.
struct Piercing {
  bool hit = false;
  int vertex = -1;
};
Piercing pierce(const Vec3& p, const Vec3& q, const Shape& t) {
  std::array<int, 3> s{};  // edge k is (v[k], v[k + 1])
  for (int k = 0; k < 3; ++k) s[k] = orient(p, q, t.v[k], t.v[(k + 1) % 3]);
  const bool positive = s[0] > 0 || s[1] > 0 || s[2] > 0, negative = s[0] < 0 || s[1] < 0 || s[2] < 0;
  if (positive && negative) return {};
  for (int k = 0; k < 3; ++k) {
    if (s[k] == 0 && s[(k + 2) % 3] == 0) return {true, k};
  }
  return {true, -1};
}

// Whether the segments pq and rs, in a common plane, cross at a point inside both, as seen in the
// projection dropping `drop` (one-to-one on their plane where the signs are strict).
bool cross_properly(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, int drop) {
  return orient2(p, q, r, drop) * orient2(p, q, s, drop) < 0 && orient2(r, s, p, drop) * orient2(r, s, q, drop) < 0;
}

// The constructed corners of small triangles are computed on the six vertices scaled up by the
// power of two that brings the largest coordinate magnitude into [1, 2) (exact: no product of
// coordinates underflows there), then scaled back. Larger ones are not scaled down, which would
// flush subnormal coordinates (and the domain's 2^300 keeps products of three finite). The exact
// signs are of the vertices as given.
struct Scale {
  int e = 0;
  Vec3 in(const Vec3& p) const { return {fp::scale2(p.x, -e), fp::scale2(p.y, -e), fp::scale2(p.z, -e)}; }
  Vec3 out(const Vec3& p) const { return {fp::scale2(p.x, e), fp::scale2(p.y, e), fp::scale2(p.z, e)}; }
};

// a + s (b - a) for s in [0, 1] (a NaN s, from rounded signs that cancel, is 0).
Vec3 along(const Vec3& a, const Vec3& b, double s) {
  s = s >= 0 ? std::min(s, 1.0) : 0.0;
  return a + s * (b - a);
}

// The segment's ends in lexicographic order, so that the rounded point does not depend on the
// direction the edge is given in.
std::pair<Vec3, Vec3> ordered(const Vec3& p, const Vec3& q) { return lexicographic_less(q, p) ? std::pair{q, p} : std::pair{p, q}; }

// Where the segment pq crosses the plane of the triangle t (pq strictly crosses it). The normal
// is taken from t's edges each scaled to unit magnitude (its direction is theirs; a tiny
// triangle's products do not underflow).
Vec3 plane_crossing(const Vec3& p0, const Vec3& q0, const Shape& t0, const Scale& scale) {
  const auto [p, q] = ordered(scale.in(p0), scale.in(q0));
  const Vec3 t = scale.in(t0.v[0]);
  const Vec3 n = cross(unit_scaled(scale.in(t0.v[1]) - t), unit_scaled(scale.in(t0.v[2]) - t));
  const double dp = dot(p - t, n), dq = dot(q - t, n);
  return scale.out(along(p, q, dp / (dp - dq)));
}

// The 2-D cross product d x w in the projection dropping `drop`.
double cross2(const Vec3& d, const Vec3& w, int drop) {
  const int i = first_kept(drop), j = second_kept(drop);
  return d[i] * w[j] - d[j] * w[i];
}

// Where the coplanar segments pq and rs cross (properly, in the projection dropping `drop`):
// on the segment whose ends come first lexicographically, so the point is the same either way;
// the other's direction scaled to unit magnitude (a tiny edge's products do not underflow).
Vec3 edge_crossing(const Vec3& p0, const Vec3& q0, const Vec3& r0, const Vec3& s0, int drop, const Scale& scale) {
  auto e = ordered(scale.in(p0), scale.in(q0)), f = ordered(scale.in(r0), scale.in(s0));
  if (lexicographic_less(f.first, e.first) || (f.first == e.first && lexicographic_less(f.second, e.second))) {
    std::swap(e, f);
  }
  const Vec3 d = unit_scaled(f.second - f.first);
  const double de = cross2(d, e.first - f.first, drop), dq = cross2(d, e.second - f.first, drop);
  return scale.out(along(e.first, e.second, de / (de - dq)));
}

// The candidate corners: each an exact corner of a n b, or its rounded value. At most 12: 3 + 3
// vertices and 3 + 3 edges crossing a plane, or 3 + 3 vertices and 6 crossing edges in a plane.
struct Candidates {
  static constexpr int kCapacity = 12;
  std::array<Vec3, kCapacity> points{};
  int count = 0;
  bool coplanar = false;  // the points span a polygon in the plane projected by `drop`
  int drop = 2;
  void add(const Vec3& p) {
    if (count < kCapacity) points[count++] = p;
  }
};

int edge_count(const Shape& s) { return s.n == 3 ? 3 : s.n - 1; }
std::pair<Vec3, Vec3> edge(const Shape& s, int i) { return {s.v[i], s.v[(i + 1) % s.n]}; }

// t (a triangle) and o in a common plane, projected by dropping `drop`: the vertices of each in
// the other, and the proper crossings of their edges.
void meet_in_plane(const Shape& t, const Shape& o, int drop, const Scale& scale, Candidates& c) {
  c.coplanar = true;
  c.drop = drop;
  for (int i = 0; i < t.n; ++i) {
    if (contains(o, t.v[i], drop)) c.add(t.v[i]);
  }
  for (int i = 0; i < o.n; ++i) {
    if (contains(t, o.v[i], drop)) c.add(o.v[i]);
  }
  for (int i = 0; i < edge_count(t); ++i) {
    const auto [p, q] = edge(t, i);
    for (int j = 0; j < edge_count(o); ++j) {
      const auto [r, s] = edge(o, j);
      if (cross_properly(p, q, r, s, drop)) c.add(edge_crossing(p, q, r, s, drop, scale));
    }
  }
}

// The vertices of o on the plane of the triangle t and in t, and the crossings of o's edges with
// that plane inside t (o not in the plane): a vertex of t as given when the edge passes through it.
void meet_across(const Shape& t, const Shape& o, const std::array<int, 3>& side, const Scale& scale, Candidates& c) {
  const int drop = t.drop;
  for (int i = 0; i < o.n; ++i) {
    if (side[i] == 0 && contains(t, o.v[i], drop)) c.add(o.v[i]);
  }
  for (int i = 0; i < edge_count(o); ++i) {
    const int j = (i + 1) % o.n;
    if (side[i] * side[j] >= 0) continue;
    const Piercing at = pierce(o.v[i], o.v[j], t);
    if (at.hit) c.add(at.vertex >= 0 ? t.v[at.vertex] : plane_crossing(o.v[i], o.v[j], t, scale));
  }
}

// The sides of o's vertices of the plane of the triangle t; whether o lies strictly on one side.
std::array<int, 3> sides(const Shape& t, const Shape& o) {
  std::array<int, 3> s{};
  for (int i = 0; i < o.n; ++i) s[i] = orient(t.v[0], t.v[1], t.v[2], o.v[i]);
  return s;
}
bool one_side(const std::array<int, 3>& s, int n) {
  return std::all_of(s.begin(), s.begin() + n, [](int x) { return x > 0; }) ||
         std::all_of(s.begin(), s.begin() + n, [](int x) { return x < 0; });
}

// A triangle t against any shape o.
void meet_triangle(const Shape& t, const Shape& o, const Scale& scale, Candidates& c) {
  const std::array<int, 3> to = sides(t, o);
  if (one_side(to, o.n)) return;
  if (std::all_of(to.begin(), to.begin() + o.n, [](int x) { return x == 0; })) {
    // Two triangles of one plane: the projection of the one whose vertices come first, so that
    // exchanging them changes nothing.
    const bool o_first = o.n == 3 && std::lexicographical_compare(o.v.begin(), o.v.end(), t.v.begin(), t.v.end(), lexicographic_less);
    meet_in_plane(t, o, (o_first ? o : t).drop, scale, c);
    return;
  }
  meet_across(t, o, to, scale, c);
  if (o.n == 3) meet_across(o, t, sides(o, t), scale, c);
}

// Two shapes of at most two points each.
void meet_degenerate(const Shape& a, const Shape& b, const Scale& scale, Candidates& c) {
  for (int i = 0; i < a.n; ++i) {
    if (contains(b, a.v[i], 0)) c.add(a.v[i]);
  }
  for (int i = 0; i < b.n; ++i) {
    if (contains(a, b.v[i], 0)) c.add(b.v[i]);
  }
  if (a.n < 2 || b.n < 2 || orient(a.v[0], a.v[1], b.v[0], b.v[1]) != 0) return;
  // Coplanar segments cross properly exactly when they do in some projection (a projection that
  // is not one-to-one on their plane makes them collinear). The best conditioned one first.
  const Vec3 m = abs(cross(a.v[1] - a.v[0], b.v[1] - b.v[0]));
  std::array<int, 3> drops{0, 1, 2};
  std::sort(drops.begin(), drops.end(), [&m](int i, int j) { return m[i] > m[j]; });
  for (int drop : drops) {
    if (cross_properly(a.v[0], a.v[1], b.v[0], b.v[1], drop)) {
      c.add(edge_crossing(a.v[0], a.v[1], b.v[0], b.v[1], drop, scale));
      return;
    }
  }
}

// The corners from the candidates: distinct, the two farthest apart when they lie on a line (the
// triangles are not coplanar), in order of angle around their mean in a plane.
TriangleIntersection corners_of(Candidates& c) {
  // Insertion sort: a dozen points at most.
  for (int i = 1; i < c.count; ++i) {
    for (int j = i; j > 0 && lexicographic_less(c.points[j], c.points[j - 1]); --j) std::swap(c.points[j], c.points[j - 1]);
  }
  c.count = static_cast<int>(std::unique(c.points.begin(), c.points.begin() + c.count) - c.points.begin());
  TriangleIntersection r;
  if (c.count == 0) return r;
  if (!c.coplanar || c.count <= 2) {
    int best_i = 0, best_j = 0;
    double best = -1;
    for (int i = 0; i < c.count; ++i) {
      for (int j = i + 1; j < c.count; ++j) {
        const Vec3 d = c.points[j] - c.points[i];
        const double d2 = d.x * d.x + d.y * d.y + d.z * d.z;
        if (d2 > best) best = d2, best_i = i, best_j = j;
      }
    }
    r.points[0] = c.points[best_i];
    r.count = 1;
    if (best_j != best_i) r.points[r.count++] = c.points[best_j];
    return r;
  }
  // The exact corners of two triangles' intersection number at most 6, and rounding only merges.
  const int i = first_kept(c.drop), j = second_kept(c.drop);
  double mi = 0, mj = 0;
  for (int k = 0; k < c.count; ++k) mi += c.points[k][i], mj += c.points[k][j];
  mi /= c.count;
  mj /= c.count;
  std::array<std::pair<double, int>, 12> angle{};
  for (int k = 0; k < c.count; ++k) angle[k] = {std::atan2(c.points[k][j] - mj, c.points[k][i] - mi), k};
  std::sort(angle.begin(), angle.begin() + c.count);
  r.count = std::min(c.count, 6);
  for (int k = 0; k < r.count; ++k) r.points[k] = c.points[angle[k].second];
  return r;
}

}  // namespace

TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b) {
  // The certified separating-axis test first: its misses are certain (it errs only toward a hit),
  // and it decides most pairs that are apart in a fraction of the exact signs' time.
  if (!finite(a) || !finite(b) || !test_triangle_triangle(a, b)) return {};
  double m = 0;
  for (const Triangle* t : {&a, &b}) {
    for (const Vec3& p : t->v) m = std::max(m, max_abs(p));
  }
  const Scale scale{m > 0 ? std::min(fp::exponent_of(m), 0) : 0};
  const Shape sa = shape_of(a), sb = shape_of(b);
  Candidates c;
  if (sa.n == 3) {
    meet_triangle(sa, sb, scale, c);
  } else if (sb.n == 3) {
    meet_triangle(sb, sa, scale, c);
  } else {
    meet_degenerate(sa, sb, scale, c);
  }
  return corners_of(c);
}

}  // namespace cc
