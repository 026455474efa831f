#include "oracle/exact/exact_triangle_intersection.h"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>

#include "oracle/exact/exact_ray_triangle.h"

namespace cc::exact {
namespace {

using Points = std::vector<QVec3>;

bool equal(const QVec3& p, const QVec3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }

void add_distinct(Points& points, const QVec3& p) {
  for (const QVec3& q : points) {
    if (equal(p, q)) return;
  }
  points.push_back(p);
}

QVec3 negated(const QVec3& v) { return Rational(-1) * v; }

// The point set of a triangle: its three vertices, or the ends of the segment (the two farthest
// apart) its collinear vertices span, or its one point.
Points point_set(const Triangle& t) {
  const std::array<QVec3, 3> v = {rational(t.v[0]), rational(t.v[1]), rational(t.v[2])};
  if (!is_zero(cross(v[1] - v[0], v[2] - v[0]))) return {v[0], v[1], v[2]};
  Points ends{v[0]};
  Rational farthest = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      const QVec3 d = v[j] - v[i];
      if (dot(d, d) > farthest) farthest = dot(d, d), ends = {v[i], v[j]};
    }
  }
  return ends;
}

// The edges of a point set: a triangle's three, a segment's one.
std::vector<std::pair<QVec3, QVec3>> edges_of(const Points& s) {
  if (s.size() == 3) return {{s[0], s[1]}, {s[1], s[2]}, {s[2], s[0]}};
  if (s.size() == 2) return {{s[0], s[1]}};
  return {};
}

QVec3 normal_of(const Points& t) { return cross(t[1] - t[0], t[2] - t[0]); }

// The part of the closed convex polygon p (a segment or a point too) where dot(m, x - o) >= 0
// (Sutherland-Hodgman).
Points clip(const Points& p, const QVec3& m, const QVec3& o) {
  Points out;
  if (p.size() == 1) {
    if (sgn(dot(m, p[0] - o)) >= 0) out.push_back(p[0]);
    return out;
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const QVec3& a = p[i];
    const QVec3& b = p[(i + 1) % p.size()];
    const Rational da = dot(m, a - o), db = dot(m, b - o);
    if (sgn(da) >= 0) add_distinct(out, a);
    if (sgn(da) * sgn(db) < 0) add_distinct(out, a + (da / (da - db)) * (b - a));
  }
  return out;
}

// A point set of at most three points clipped to the closed triangle t: its plane from both
// sides, then the three planes through its edges perpendicular to it, facing inwards.
Points clip_to_triangle(Points p, const Points& t) {
  const QVec3 n = normal_of(t);
  p = clip(p, n, t[0]);
  p = clip(p, negated(n), t[0]);
  for (int k = 0; k < 3 && !p.empty(); ++k) p = clip(p, cross(n, t[(k + 1) % 3] - t[k]), t[k]);
  return p;
}

// Two point sets of at most two points each (segments, points).
Points meet_small(const Points& a, const Points& b) {
  if (a.size() == 1 || b.size() == 1) {
    const Points& point = a.size() == 1 ? a : b;
    const Points& other = a.size() == 1 ? b : a;
    const bool meets = other.size() == 1 ? equal(point[0], other[0]) : on_segment(point[0], other[0], other[1]);
    return meets ? point : Points{};
  }
  const QVec3 d1 = a[1] - a[0], d2 = b[1] - b[0], w = b[0] - a[0];
  const QVec3 m = cross(d1, d2);
  if (is_zero(m)) {  // parallel: on one line or apart
    if (!is_zero(cross(d1, w))) return {};
    const Rational dd = dot(d1, d1);
    Rational s0 = dot(w, d1) / dd, s1 = dot(b[1] - a[0], d1) / dd;
    if (s0 > s1) std::swap(s0, s1);
    const Rational lo = std::max(s0, Rational(0)), hi = std::min(s1, Rational(1));
    if (lo > hi) return {};
    Points out;
    add_distinct(out, a[0] + lo * d1);
    add_distinct(out, a[0] + hi * d1);
    return out;
  }
  if (sgn(dot(m, w)) != 0) return {};  // skew
  const Rational mm = dot(m, m);
  const Rational s = dot(cross(w, d2), m) / mm, t = dot(cross(w, d1), m) / mm;
  if (s < 0 || s > 1 || t < 0 || t > 1) return {};
  return {a[0] + s * d1};
}

// The two farthest apart of collinear points.
Points ends_of_line(const Points& p) {
  std::size_t bi = 0, bj = 0;
  Rational farthest = -1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const QVec3 d = p[j] - p[i];
      if (dot(d, d) > farthest) farthest = dot(d, d), bi = i, bj = j;
    }
  }
  return {p[bi], p[bj]};
}

bool collinear(const Points& p) {
  for (std::size_t i = 2; i < p.size(); ++i) {
    if (!is_zero(cross(p[1] - p[0], p[i] - p[0]))) return false;
  }
  return true;
}

Magnitude longest_edge2(const Points& t) {
  Rational longest = 0;
  for (const auto& [p, q] : edges_of(t)) longest = std::max(longest, dot(q - p, q - p));
  return Magnitude::of(longest);
}

// c = L^2 / |n| of a triangle: how ill-determined its plane is (at least 1).
Magnitude plane_condition(const Points& t) { return longest_edge2(t) / length(normal_of(t)); }

bool coplanar(const Points& a, const Points& b) {
  const auto all_on = [](const Points& t, const Points& o) {
    const QVec3 n = normal_of(t);
    return std::all_of(o.begin(), o.end(), [&](const QVec3& q) { return sgn(dot(n, q - t[0])) == 0; });
  };
  if (a.size() == 3) return all_on(a, b);
  if (b.size() == 3) return all_on(b, a);
  if (a.size() < 2 || b.size() < 2) return true;
  return sgn(dot(cross(a[1] - a[0], b[1] - b[0]), b[0] - a[0])) == 0;
}

// The condition number of the library's rounded corner at v (see ExactCorner).
double condition_at(const QVec3& v, const Points& a, const Points& b) {
  for (const Points* s : {&a, &b}) {
    for (const QVec3& p : *s) {
      if (equal(p, v)) return 1;
    }
  }
  double kappa = 1;
  if (!coplanar(a, b)) {
    // An edge of x crossing the plane of the triangle y strictly, through v: c_y / sin phi
    // = L_y^2 |e| / |e . n_y|.
    for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
      if (y->size() != 3) continue;
      const QVec3 n = normal_of(*y);
      const Magnitude longest2 = longest_edge2(*y);
      for (const auto& [p, q] : edges_of(*x)) {
        if (!on_segment(v, p, q) || sgn(dot(n, p - (*y)[0])) * sgn(dot(n, q - (*y)[0])) >= 0) continue;
        const Rational en = dot(q - p, n);
        kappa = std::max(kappa, (longest2 * length(q - p) / Magnitude::of(en >= 0 ? en : Rational(-en))).to_double());
      }
    }
    return kappa;
  }
  // Two edges crossing in the common plane: c / sin psi = c |e| |f| / |e x f|.
  Magnitude c = Magnitude::of(Rational(1));
  for (const Points* s : {&a, &b}) {
    if (s->size() == 3) {
      const Magnitude cs = plane_condition(*s);
      if (cs.to_double() > c.to_double()) c = cs;
    }
  }
  for (const auto& [p, q] : edges_of(a)) {
    for (const auto& [r, s] : edges_of(b)) {
      const QVec3 exf = cross(q - p, s - r);
      if (is_zero(exf) || !on_segment(v, p, q) || !on_segment(v, r, s)) continue;
      kappa = std::max(kappa, (c * length(q - p) * length(s - r) / length(exf)).to_double());
    }
  }
  return kappa;
}

}  // namespace

std::vector<ExactCorner> exact_triangle_intersection(const Triangle& a, const Triangle& b) {
  const Points pa = point_set(a), pb = point_set(b);
  Points points = pb.size() == 3   ? clip_to_triangle(pa, pb)
                  : pa.size() == 3 ? clip_to_triangle(pb, pa)
                                   : meet_small(pa, pb);
  if (points.size() > 2 && collinear(points)) points = ends_of_line(points);
  std::vector<ExactCorner> corners;
  for (const QVec3& p : points) corners.push_back({p, condition_at(p, pa, pb)});
  return corners;
}

Rational distance2_to_hull(const QVec3& p, const std::vector<QVec3>& points) {
  // Every point of the hull of coplanar points lies in a triangle of three of them (Caratheodory).
  std::optional<Rational> best;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) {
      for (std::size_t k = j; k < n; ++k) {
        const Rational d = distance2_to_triangle(p, {points[i], points[j], points[k]});
        if (!best || d < *best) best = d;
      }
    }
  }
  return best.value_or(Rational(0));
}

}  // namespace cc::exact
