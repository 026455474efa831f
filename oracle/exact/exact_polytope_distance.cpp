#include "oracle/exact/exact_polytope_distance.h"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "oracle/exact/exact_distance.h"

namespace cc::exact {

std::array<QVec3, 8> box_corners(const Obb& box) {
  const QVec3 c = rational(box.center);
  QVec3 half_edge[3];
  for (int k = 0; k < 3; ++k) half_edge[k] = rational(box.half[k]) * rational(box.axes.col[k]);
  std::array<QVec3, 8> corners;
  for (int bits = 0; bits < 8; ++bits) {
    QVec3 p = c;
    for (int k = 0; k < 3; ++k) p = (bits >> k & 1) ? p + half_edge[k] : p - half_edge[k];
    corners[bits] = p;
  }
  return corners;
}

std::array<QVec3, 3> triangle_corners(const Triangle& t) { return {rational(t.v[0]), rational(t.v[1]), rational(t.v[2])}; }

namespace {

const QVec3 kOrigin{0, 0, 0};

// A face of the hull: its corners (outward by the right-hand rule), its outward normal n and its
// plane's offset n . corner; a point x lies outside it when n . x > offset.
struct Face {
  std::array<int, 3> v;
  QVec3 normal;
  Rational offset;
  bool alive = true;
};

Face face_of(const std::vector<QVec3>& p, int a, int b, int c) {
  Face f{{a, b, c}, cross(p[b] - p[a], p[c] - p[a]), 0};
  f.offset = dot(f.normal, p[a]);
  return f;
}

// Four points spanning space, if the points do: the first, the first other, the first off their
// line, the first off their plane.
std::optional<std::array<int, 4>> spanning(const std::vector<QVec3>& p, int& rank, std::array<int, 3>& basis) {
  const int n = static_cast<int>(p.size());
  rank = 0;
  basis = {0, 0, 0};
  int i1 = 1;
  while (i1 < n && is_zero(p[i1] - p[0])) ++i1;
  if (i1 == n) return std::nullopt;
  rank = 1, basis[1] = i1;
  int i2 = i1 + 1;
  while (i2 < n && is_zero(cross(p[i1] - p[0], p[i2] - p[0]))) ++i2;
  if (i2 >= n) return std::nullopt;
  rank = 2, basis[2] = i2;
  const QVec3 normal = cross(p[i1] - p[0], p[i2] - p[0]);
  int i3 = i2 + 1;
  while (i3 < n && sgn(dot(normal, p[i3] - p[0])) == 0) ++i3;
  if (i3 >= n) return std::nullopt;
  rank = 3;
  return std::array<int, 4>{0, i1, i2, i3};
}

// The faces of the hull of points spanning space, by the incremental algorithm: each point
// outside the hull so far (strictly, so points on it add nothing) replaces the faces it sees by a
// fan from their horizon to it.
std::vector<Face> hull(const std::vector<QVec3>& p, const std::array<int, 4>& start) {
  std::vector<Face> faces;
  std::map<std::pair<int, int>, int> edge_face;  // directed edge (u, v) of a live face -> that face
  const auto add = [&](int a, int b, int c) {
    faces.push_back(face_of(p, a, b, c));
    const int index = static_cast<int>(faces.size()) - 1;
    for (int k = 0; k < 3; ++k) edge_face[{faces.back().v[k], faces.back().v[(k + 1) % 3]}] = index;
  };
  const auto [s0, s1, s2, s3] = start;
  // The tetrahedron, each face turned so that the fourth corner lies inside it.
  const bool flip = sgn(dot(cross(p[s1] - p[s0], p[s2] - p[s0]), p[s3] - p[s0])) > 0;
  for (const auto& [a, b, c] : {std::array{s0, s1, s2}, {s0, s3, s1}, {s1, s3, s2}, {s0, s2, s3}}) {
    if (flip) {
      add(a, c, b);
    } else {
      add(a, b, c);
    }
  }
  for (int i = 0; i < static_cast<int>(p.size()); ++i) {
    if (i == s0 || i == s1 || i == s2 || i == s3) continue;
    std::vector<int> seen;
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
      if (faces[f].alive && dot(faces[f].normal, p[i]) > faces[f].offset) seen.push_back(f);
    }
    if (seen.empty()) continue;
    for (int f : seen) faces[f].alive = false;
    std::vector<std::pair<int, int>> horizon;
    for (int f : seen) {
      for (int k = 0; k < 3; ++k) {
        const int u = faces[f].v[k], v = faces[f].v[(k + 1) % 3];
        if (!faces[edge_face.at({v, u})].alive) continue;  // shared with another face it sees
        horizon.push_back({u, v});
      }
    }
    for (int f : seen) {
      for (int k = 0; k < 3; ++k) edge_face.erase({faces[f].v[k], faces[f].v[(k + 1) % 3]});
    }
    for (const auto& [u, v] : horizon) add(u, v, i);
  }
  std::erase_if(faces, [](const Face& f) { return !f.alive; });
  return faces;
}

// Points in a plane (normal n) as the corners of their hull in it, in order, by the monotone
// chain on the two coordinates across the normal's largest one.
std::vector<QVec3> polygon(std::vector<QVec3> p, const QVec3& n) {
  int drop = 0;
  for (int k = 1; k < 3; ++k) {
    if (abs(n[k]) > abs(n[drop])) drop = k;
  }
  const int x = (drop + 1) % 3, y = (drop + 2) % 3;
  std::sort(p.begin(), p.end(), [&](const QVec3& a, const QVec3& b) { return a[x] < b[x] || (a[x] == b[x] && a[y] < b[y]); });
  const auto turn = [&](const QVec3& o, const QVec3& a, const QVec3& b) {
    return sgn((a[x] - o[x]) * (b[y] - o[y]) - (a[y] - o[y]) * (b[x] - o[x]));
  };
  std::vector<QVec3> chain;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t floor = chain.size();
    for (const QVec3& q : p) {
      while (chain.size() >= floor + 2 && turn(chain[chain.size() - 2], chain.back(), q) <= 0) chain.pop_back();
      chain.push_back(q);
    }
    chain.pop_back();  // the last of a pass is the first of the next
    std::reverse(p.begin(), p.end());
  }
  return chain;
}

// The points' hull has no inside: 0 where it holds the origin, else the squared distance to it.
ExactSignedDistance flat(const std::vector<QVec3>& p, int rank, const std::array<int, 3>& basis) {
  Rational least;
  if (rank == 0) {
    least = dot(p[0], p[0]);
  } else if (rank == 1) {
    // The segment between the least and the greatest along the line.
    const QVec3 g = p[basis[1]] - p[0];
    int lo = 0, hi = 0;
    for (int i = 1; i < static_cast<int>(p.size()); ++i) {
      if (dot(g, p[i]) < dot(g, p[lo])) lo = i;
      if (dot(g, p[i]) > dot(g, p[hi])) hi = i;
    }
    least = squared_distance_to_segment(kOrigin, p[lo], p[hi]);
  } else {
    const std::vector<QVec3> corners = polygon(p, cross(p[basis[1]] - p[0], p[basis[2]] - p[0]));
    least = squared_distance_to_segment(kOrigin, corners[0], corners[1]);
    for (std::size_t k = 1; k + 1 < corners.size() && sgn(least) > 0; ++k) {
      const Rational d = squared_distance_to_triangle(kOrigin, QTriangle{corners[0], corners[k], corners[k + 1]});
      if (d < least) least = d;
    }
  }
  return {least, 1, 0};
}

}  // namespace

ExactSignedDistance exact_polytope_distance(std::span<const QVec3> a, std::span<const QVec3> b) {
  std::vector<QVec3> m;
  m.reserve(a.size() * b.size());
  for (const QVec3& p : a) {
    for (const QVec3& q : b) m.push_back(p - q);
  }
  int rank = 0;
  std::array<int, 3> basis;
  const auto start = spanning(m, rank, basis);
  if (!start) return flat(m, rank, basis);
  const std::vector<Face> faces = hull(m, *start);
  // The origin outside a face (offset < 0) lies outside M: its distance is to the faces it sees.
  // Else it is inside or on it, at the least distance to a face's plane, offset^2 / |n|^2.
  std::optional<Rational> outside, inside;
  for (const Face& f : faces) {
    if (sgn(f.offset) < 0) {
      const Rational d = squared_distance_to_triangle(kOrigin, QTriangle{m[f.v[0]], m[f.v[1]], m[f.v[2]]});
      if (!outside || d < *outside) outside = d;
    } else if (!outside) {
      const Rational d = f.offset * f.offset / dot(f.normal, f.normal);
      if (!inside || d < *inside) inside = d;
    }
  }
  if (outside) return {*outside, 1, 0};
  return {*inside, sgn(*inside) > 0 ? -1 : 1, 0};
}

}  // namespace cc::exact
