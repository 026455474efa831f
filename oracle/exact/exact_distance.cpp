#include "oracle/exact/exact_distance.h"

#include <array>
#include <optional>
#include <utility>
#include <stdexcept>

namespace cc::exact {
namespace {

using QMat = std::array<std::array<Rational, 3>, 3>;

Rational det3(const QMat& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

std::array<QVec3, 3> axes_of(const Obb& box) {
  return {rational(box.axes.col[0]), rational(box.axes.col[1]), rational(box.axes.col[2])};
}

// Solves the n x n system m x = r (n <= 3) by Cramer's rule; nothing when it is singular.
std::optional<std::array<Rational, 3>> solve(int n, QMat m, const std::array<Rational, 3>& r) {
  for (int i = n; i < 3; ++i) {  // pad to 3 x 3 with the identity
    for (int j = 0; j < 3; ++j) m[i][j] = m[j][i] = 0;
    m[i][i] = 1;
  }
  const Rational det = det3(m);
  if (det == 0) return std::nullopt;
  std::array<Rational, 3> x;
  for (int k = 0; k < n; ++k) {
    QMat mk = m;
    for (int i = 0; i < 3; ++i) mk[i][k] = i < n ? r[i] : Rational(0);
    x[k] = det3(mk) / det;
  }
  return x;
}

}  // namespace

QVec3 box_coordinates(const QVec3& point, const Obb& box) {
  const std::array<QVec3, 3> a = axes_of(box);
  const QVec3 d = point - rational(box.center);
  QMat m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i][j] = a[j][i];
  }
  const auto q = solve(3, m, {d.x, d.y, d.z});
  if (!q) throw std::domain_error("box_coordinates: the box's axes are dependent");
  return {(*q)[0], (*q)[1], (*q)[2]};
}

bool in_box(const QVec3& point, const Obb& box) {
  const QVec3 q = box_coordinates(point, box);
  const QVec3 h = rational(box.half);
  for (int i = 0; i < 3; ++i) {
    if (abs(q[i]) > h[i]) return false;
  }
  return true;
}

Rational squared_distance_to_box(const QVec3& point, const Obb& box) {
  const std::array<QVec3, 3> a = axes_of(box);
  const QVec3 d = point - rational(box.center);
  const QVec3 h = rational(box.half);
  std::optional<Rational> best;
  for (int code = 0; code < 27; ++code) {
    // Coordinate i: 0 free, 1 at -half, 2 at +half.
    std::array<int, 3> hold{code % 3, code / 3 % 3, code / 9};
    QVec3 q;
    QVec3 rest = d;  // d minus the held coordinates' part
    std::array<int, 3> free{};
    int n = 0;
    for (int i = 0; i < 3; ++i) {
      if (hold[i] == 0) {
        free[n++] = i;
      } else {
        q[i] = hold[i] == 1 ? Rational(-h[i]) : h[i];
        rest = rest - q[i] * a[i];
      }
    }
    if (n > 0) {  // the normal equations of the free coordinates: a_F^T a_F q_F = a_F^T rest
      QMat m;
      std::array<Rational, 3> r;
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) m[i][j] = dot(a[free[i]], a[free[j]]);
        r[i] = dot(a[free[i]], rest);
      }
      const auto x = solve(n, m, r);
      if (!x) throw std::domain_error("squared_distance_to_box: the box's axes are dependent");
      bool inside = true;
      for (int i = 0; i < n; ++i) {
        q[free[i]] = (*x)[i];
        inside = inside && abs((*x)[i]) <= h[free[i]];
      }
      if (!inside) continue;
    }
    const QVec3 gap = (q[0] * a[0] + q[1] * a[1]) + q[2] * a[2] - d;
    const Rational squared = dot(gap, gap);
    if (!best || squared < *best) best = squared;
  }
  return *best;  // the clamp of every coordinate (no coordinate free) is always in the box
}

Rational squared_depth_in_box(const QVec3& point, const Obb& box) {
  const std::array<QVec3, 3> a = axes_of(box);
  const QVec3 q = box_coordinates(point, box);
  const QVec3 h = rational(box.half);
  std::optional<Rational> best;
  for (int i = 0; i < 3; ++i) {
    // The faces q_i = +-h_i, whose planes are spanned by the other two axes: the distance to
    // such a plane is (h_i -+ q_i) |a_i . n| / |n|, n the normal of the plane.
    const QVec3 n = cross(a[(i + 1) % 3], a[(i + 2) % 3]);
    const Rational along = dot(a[i], n);
    const Rational scale = along * along / dot(n, n);
    for (const Rational& room : {Rational(h[i] - q[i]), Rational(h[i] + q[i])}) {
      const Rational squared = room * room * scale;
      if (!best || squared < *best) best = squared;
    }
  }
  return *best;
}

Rational squared_distance_to_segment(const QVec3& point, const QVec3& from, const QVec3& to) {
  const QVec3 d = to - from;
  const Rational dd = dot(d, d);
  Rational t = 0;
  if (dd != 0) {
    t = dot(point - from, d) / dd;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
  }
  const QVec3 gap = point - (from + t * d);
  return dot(gap, gap);
}

Rational squared_distance_to_segment(const QVec3& point, const Segment& segment) {
  return squared_distance_to_segment(point, rational(segment.a), rational(segment.b));
}

namespace {

Rational squared_distance_between_segments(const QVec3& a0, const QVec3& a1, const QVec3& b0, const QVec3& b1) {
  Rational best = squared_distance_to_segment(a0, b0, b1);
  for (const Rational& c : {squared_distance_to_segment(a1, b0, b1), squared_distance_to_segment(b0, a0, a1),
                            squared_distance_to_segment(b1, a0, a1)}) {
    if (c < best) best = c;
  }
  // The interior pair: a0 + s da - (b0 + t db) perpendicular to da and db.
  const QVec3 da = a1 - a0, db = b1 - b0, r = a0 - b0;
  const Rational aa = dot(da, da), bb = dot(db, db), ab = dot(da, db);
  const Rational denom = aa * bb - ab * ab;
  if (denom != 0) {
    const Rational c = dot(da, r), f = dot(db, r);
    const Rational s = (ab * f - c * bb) / denom, t = (aa * f - ab * c) / denom;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
      const QVec3 gap = (a0 + s * da) - (b0 + t * db);
      const Rational g = dot(gap, gap);
      if (g < best) best = g;
    }
  }
  return best;
}

// The foot of p on t's plane and whether it lies in t (t not degenerate: a nonzero normal).
bool foot_in_triangle(const QVec3& p, const QTriangle& t, const QVec3& n, QVec3& foot) {
  foot = p - (dot(p - t[0], n) / dot(n, n)) * n;
  for (int i = 0; i < 3; ++i) {
    if (dot(cross(t[(i + 1) % 3] - t[i], foot - t[i]), n) < 0) return false;
  }
  return true;
}

}  // namespace

Rational squared_distance_between_segments(const Segment& a, const Segment& b) {
  return squared_distance_between_segments(rational(a.a), rational(a.b), rational(b.a), rational(b.b));
}

QTriangle rational_triangle(const Triangle& t) { return {rational(t.v[0]), rational(t.v[1]), rational(t.v[2])}; }

Rational squared_distance_to_triangle(const QVec3& point, const QTriangle& t) {
  const QVec3 n = cross(t[1] - t[0], t[2] - t[0]);
  QVec3 foot;
  if (!is_zero(n) && foot_in_triangle(point, t, n, foot)) {
    const QVec3 gap = point - foot;
    return dot(gap, gap);
  }
  Rational best = squared_distance_to_segment(point, t[0], t[1]);
  for (int i = 1; i < 3; ++i) {
    const Rational d = squared_distance_to_segment(point, t[i], t[(i + 1) % 3]);
    if (d < best) best = d;
  }
  return best;
}

Rational squared_distance_to_triangle(const QVec3& point, const Triangle& triangle) {
  return squared_distance_to_triangle(point, rational_triangle(triangle));
}

Rational squared_distance_between_triangles(const QTriangle& a, const QTriangle& b) {
  // An edge of one meeting the other (not degenerate) triangle: its endpoints on both sides of
  // the plane or on it, and the crossing in the triangle. (An edge in the plane meets the
  // triangle through an edge or a vertex, which the pairs below find at 0.)
  for (const auto& [from, to] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    const QTriangle& t = *to;
    const QVec3 n = cross(t[1] - t[0], t[2] - t[0]);
    if (is_zero(n)) continue;
    for (int i = 0; i < 3; ++i) {
      const QVec3& p = (*from)[i];
      const QVec3& q = (*from)[(i + 1) % 3];
      const Rational dp = dot(p - t[0], n), dq = dot(q - t[0], n);
      if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) continue;
      const QVec3 at = p + Rational(dp / (dp - dq)) * (q - p);
      QVec3 foot;
      if (foot_in_triangle(at, t, n, foot)) return 0;
    }
  }
  Rational best = squared_distance_to_triangle(b[0], a);
  for (int i = 0; i < 3; ++i) {
    for (const Rational& d : {squared_distance_to_triangle(a[i], b), squared_distance_to_triangle(b[(i + 1) % 3], a)}) {
      if (d < best) best = d;
    }
    for (int j = 0; j < 3; ++j) {
      const Rational d = squared_distance_between_segments(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]);
      if (d < best) best = d;
    }
  }
  return best;
}

Rational squared_distance_between_triangles(const Triangle& a, const Triangle& b) {
  return squared_distance_between_triangles(rational_triangle(a), rational_triangle(b));
}

bool root_within(const Rational& square, const Rational& y, const Rational& e) {
  const Rational lo = y - e, hi = y + e;
  if (hi < 0) return false;
  if (square > hi * hi) return false;
  return lo <= 0 || square >= lo * lo;
}

}  // namespace cc::exact
