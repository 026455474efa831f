// The exact separating-axis test, on hand-worked cases and against an independent method:
// whether the origin lies in the convex hull of the vertex differences, by Caratheodory (the
// origin is in the hull iff it is in some simplex of at most four affinely independent
// differences), with exact barycentric coordinates.
#include "oracle/exact/convex_sat.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace cc::exact {
namespace {

// Whether 0 lies in the simplex spanned by s (1 to 4 points), exactly. False for affinely
// dependent points (a larger hull is covered by its independent subsets).
bool origin_in_simplex(const std::vector<QVec3>& s) {
  switch (s.size()) {
    case 1: return is_zero(s[0]);
    case 2: {
      const QVec3 d = s[1] - s[0];
      if (is_zero(d) || !is_zero(cross(s[0], s[1]))) return false;
      return sgn(dot(s[0], s[1])) <= 0;  // collinear with 0, and 0 between them
    }
    case 3: {
      const QVec3 n = cross(s[1] - s[0], s[2] - s[0]);
      if (is_zero(n) || sgn(dot(n, s[0])) != 0) return false;  // not a triangle, or 0 off its plane
      const int a = sgn(dot(n, cross(s[1], s[2]))), b = sgn(dot(n, cross(s[2], s[0]))),
                c = sgn(dot(n, cross(s[0], s[1])));
      return a >= 0 && b >= 0 && c >= 0;
    }
    default: {
      const auto det = [](const QVec3& p, const QVec3& q, const QVec3& r) { return dot(p, cross(q, r)); };
      // 0 = s0 + a (s1 - s0) + b (s2 - s0) + c (s3 - s0), by Cramer's rule.
      const QVec3 e1 = s[1] - s[0], e2 = s[2] - s[0], e3 = s[3] - s[0], r = QVec3{0, 0, 0} - s[0];
      const Rational total = det(e1, e2, e3);
      if (sgn(total) == 0) return false;
      const Rational a = det(r, e2, e3) / total, b = det(e1, r, e3) / total, c = det(e1, e2, r) / total;
      return sgn(a) >= 0 && sgn(b) >= 0 && sgn(c) >= 0 && a + b + c <= 1;
    }
  }
}

bool origin_in_hull(const std::vector<QVec3>& points) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (origin_in_simplex({points[i]})) return true;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (origin_in_simplex({points[i], points[j]})) return true;
      for (std::size_t k = j + 1; k < n; ++k) {
        if (origin_in_simplex({points[i], points[j], points[k]})) return true;
        for (std::size_t l = k + 1; l < n; ++l) {
          if (origin_in_simplex({points[i], points[j], points[k], points[l]})) return true;
        }
      }
    }
  }
  return false;
}

std::vector<QVec3> differences(const std::vector<QVec3>& a, const std::vector<QVec3>& b) {
  std::vector<QVec3> d;
  for (const QVec3& p : a) {
    for (const QVec3& q : b) d.push_back(p - q);
  }
  return d;
}

std::vector<QVec3> box_corners(const Vec3& lo, const Vec3& hi) {
  std::vector<QVec3> c;
  for (int i = 0; i < 8; ++i) {
    c.push_back(rational(Vec3{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z}));
  }
  return c;
}

TEST(ExactSat, HandWorkedTriangles) {
  // Coplanar, apart across the hypotenuse by sqrt(2)/2: margin -sqrt(0.5).
  const SatResult apart = exact_sat(triangle_shape({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "A"),
                                    triangle_shape({1, 1, 0}, {2, 1, 0}, {1, 2, 0}, "B"));
  EXPECT_FALSE(apart.hit);
  EXPECT_EQ(apart.rank, 2);
  EXPECT_NEAR(apart.margin, -std::sqrt(0.5), 1e-15);
  // Parallel planes one apart: separated by the normal, with the normal's conditioning (|e0||e1|).
  const SatResult planes = exact_sat(triangle_shape({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "A"),
                                     triangle_shape({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, "B"));
  EXPECT_FALSE(planes.hit);
  EXPECT_EQ(planes.rank, 2);
  // Two parallel segments a unit apart: rank 1, separated across the line at distance 1.
  const SatResult segments = exact_sat(triangle_shape({0, 0, 0}, {2, 0, 0}, {1, 0, 0}, "A"),
                                       triangle_shape({0, 1, 0}, {2, 1, 0}, {1, 1, 0}, "B"));
  EXPECT_FALSE(segments.hit);
  EXPECT_EQ(segments.rank, 1);
  EXPECT_DOUBLE_EQ(segments.margin, -1);
  // Two points 3 apart: rank 0.
  const SatResult points = exact_sat(triangle_shape({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, "A"),
                                     triangle_shape({0, 3, 0}, {0, 3, 0}, {0, 3, 0}, "B"));
  EXPECT_FALSE(points.hit);
  EXPECT_DOUBLE_EQ(points.margin, -3);
}

TEST(ExactSat, HandWorkedBoxes) {
  // Unit cubes overlapping by 0.25 along x: penetration depth 0.25.
  const SatResult overlap = exact_sat(box_shape({0, 0, 0}, {1, 1, 1}, "A"), box_shape({0.75, 0, 0}, {1.75, 1, 1}, "B"));
  EXPECT_TRUE(overlap.hit);
  EXPECT_EQ(overlap.rank, 3);
  EXPECT_DOUBLE_EQ(overlap.margin, 0.25);
  // Touching at a face: depth 0.
  const SatResult touching = exact_sat(box_shape({0, 0, 0}, {1, 1, 1}, "A"), box_shape({1, 0, 0}, {2, 1, 1}, "B"));
  EXPECT_TRUE(touching.hit);
  EXPECT_EQ(touching.margin, 0);
  // A sheared parallelepiped: columns (1,0,0) and (1,1,0), half extents 1: it reaches x = 2.
  const ExactShape sheared = parallelepiped_shape({0, 0, 0}, {1, 1, 1}, Mat3::from_columns({1, 0, 0}, {1, 1, 0}, {0, 0, 1}), "S");
  EXPECT_TRUE(exact_sat(sheared, box_shape({2, 0, 0}, {3, 1, 1}, "B")).hit);
  EXPECT_FALSE(exact_sat(sheared, box_shape({2.5, 0, 0}, {3, 1, 1}, "B")).hit);
}

// Small integer coordinates make coplanar, collinear, touching and degenerate shapes common.
class SmallIntegers {
 public:
  explicit SmallIntegers(unsigned seed) : rng_(seed) {}
  double next() { return static_cast<double>(std::uniform_int_distribution<int>(-2, 2)(rng_)); }
  Vec3 point() { return {next(), next(), next()}; }

 private:
  std::mt19937 rng_;
};

TEST(ExactSat, AgreesWithHullContainmentOnTriangles) {
  SmallIntegers g(1);
  int hits = 0, degenerate = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 a[3] = {g.point(), g.point(), g.point()}, b[3] = {g.point(), g.point(), g.point()};
    const ExactShape sa = triangle_shape(a[0], a[1], a[2], "A"), sb = triangle_shape(b[0], b[1], b[2], "B");
    const bool expected = origin_in_hull(differences(sa.vertices, sb.vertices));
    const SatResult r = exact_sat(sa, sb);
    ASSERT_EQ(r.hit, expected) << "case " << i;
    hits += expected;
    degenerate += r.rank < 3;
  }
  EXPECT_GT(hits, 300);
  EXPECT_GT(degenerate, 10);
}

TEST(ExactSat, AgreesWithHullContainmentOnTrianglesAndBoxes) {
  SmallIntegers g(2);
  int hits = 0;
  for (int i = 0; i < 150; ++i) {
    Vec3 lo = g.point(), hi = g.point();
    for (int k = 0; k < 3; ++k) {
      if (lo[k] > hi[k]) std::swap(lo[k], hi[k]);
      if (i % 3 == 0) hi[k] = lo[k];  // boxes of zero extent: points, segments, rectangles
    }
    const Vec3 t[3] = {g.point(), g.point(), g.point()};
    const ExactShape box = box_shape(lo, hi, "B"), tri = triangle_shape(t[0], t[1], t[2], "T");
    const bool expected = origin_in_hull(differences(box_corners(lo, hi), tri.vertices));
    ASSERT_EQ(exact_sat(box, tri).hit, expected) << "case " << i;
    hits += expected;
  }
  EXPECT_GT(hits, 15);
}

}  // namespace
}  // namespace cc::exact
