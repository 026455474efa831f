#include "collide/kdop_support.h"

#include <cmath>
#include <vector>

namespace cc {
namespace {

// A face of the convex hull of the normalised half-space normals: its three normals and the
// inverse of the matrix with them as columns (adjugate over determinant, both small integers:
// one rounding per entry).
struct Face {
  std::array<int, 3> normal;
  std::array<Vec3, 3> inverse_rows;
};

template <int K>
Vec3 half_space_normal(int h) {
  const KdopDirection d = kdop_directions<K>()[h % (K / 2)];
  const double sign = h < K / 2 ? 1.0 : -1.0;
  return {sign * d.x, sign * d.y, sign * d.z};
}

// Every triple of normalised normals whose plane has all the others on its inner side (with
// four or more on one plane, every triple of them: the faces then overlap, which is harmless).
// Found once per K by brute force, in floating point: the hull only chooses which triples to
// try; any triple whose cone holds m gives a valid bound.
template <int K>
std::vector<Face> hull_faces() {
  std::array<Vec3, K> unit;
  for (int h = 0; h < K; ++h) {
    const Vec3 n = half_space_normal<K>(h);
    unit[h] = (1 / std::sqrt(dot(n, n))) * n;
  }
  std::vector<Face> faces;
  for (int a = 0; a < K; ++a) {
    for (int b = a + 1; b < K; ++b) {
      for (int c = b + 1; c < K; ++c) {
        Vec3 out = cross(unit[b] - unit[a], unit[c] - unit[a]);
        if (dot(out, out) < 1e-12) continue;
        if (dot(out, unit[a]) < 0) out = -1.0 * out;
        const double level = dot(out, unit[a]);
        bool face = level > 1e-9;
        for (int q = 0; q < K && face; ++q) face = dot(out, unit[q]) <= level + 1e-9;
        if (!face) continue;
        const Vec3 sa = half_space_normal<K>(a), sb = half_space_normal<K>(b), sc = half_space_normal<K>(c);
        const double det = dot(sa, cross(sb, sc));  // a small integer
        const auto over_det = [det](const Vec3& r) { return Vec3{r.x / det, r.y / det, r.z / det}; };
        faces.push_back({{a, b, c}, {over_det(cross(sb, sc)), over_det(cross(sc, sa)), over_det(cross(sa, sb))}});
      }
    }
  }
  return faces;
}

}  // namespace

// The face whose smallest coefficient is largest (the first with all coefficients >= 0, which
// some face has in exact arithmetic), its coefficients clamped at 0. Each coefficient is off
// by at most 4u |inverse row|_1 |m|_max before clamping (the inverse's rounding, the products'
// and sum3's), and clamping moves it by no more; |inverse row|_1 is at most 3 over the faces of
// these direction sets (2 for k = 6, 14, 26), and each component of the combination sums three
// terms, so the combination is off by at most 3 * 24u |m|_max < 2^-46 |m|_max. The
// coefficients sum to at most 9 |m|_max.
template <int K>
KdopCone<K> kdop_cone(const Vec3& m) {
  static const std::vector<Face> faces = hull_faces<K>();
  KdopCone<K> best;
  double best_least = -INFINITY;
  for (const Face& f : faces) {
    const Vec3 c{dot(f.inverse_rows[0], m), dot(f.inverse_rows[1], m), dot(f.inverse_rows[2], m)};
    const double least = std::min({c.x, c.y, c.z});
    if (least > best_least) {
      best_least = least;
      best.normal = f.normal;
      best.coefficient = {std::max(c.x, 0.0), std::max(c.y, 0.0), std::max(c.z, 0.0)};
      if (least >= 0) break;
    }
  }
  return best;
}

template KdopCone<6> kdop_cone<6>(const Vec3&);
template KdopCone<14> kdop_cone<14>(const Vec3&);
template KdopCone<16> kdop_cone<16>(const Vec3&);
template KdopCone<18> kdop_cone<18>(const Vec3&);
template KdopCone<24> kdop_cone<24>(const Vec3&);
template KdopCone<26> kdop_cone<26>(const Vec3&);

}  // namespace cc
