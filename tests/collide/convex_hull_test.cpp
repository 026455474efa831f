#include "collide/convex_hull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace cc {
namespace {

double area(std::span<const Vec3> p, const ConvexHull& h) {
  double a = 0;
  for (const auto& t : h.triangles) {
    const Vec3 n = cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
    a += 0.5 * std::sqrt(dot(n, n));
  }
  return a;
}

bool has(const ConvexHull& h, std::uint32_t v) { return std::find(h.vertices.begin(), h.vertices.end(), v) != h.vertices.end(); }

TEST(ConvexHull, CubeWithAnInnerPoint) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  p.push_back({0.5, 0.5, 0.5});
  const ConvexHull h = convex_hull(p);
  EXPECT_EQ(h.triangles.size(), 12u);
  EXPECT_NEAR(area(p, h), 6, 1e-12);
  for (std::uint32_t v = 0; v < 8; ++v) EXPECT_TRUE(has(h, v));
  EXPECT_FALSE(has(h, 8));
}

TEST(ConvexHull, FlatPointsCoverThePolygonOnBothSides) {
  // A unit square in the plane z = 2 with a point inside and one on an edge.
  const std::vector<Vec3> p = {{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}, {0.25, 0.5, 2}, {0.5, 0, 2}};
  const ConvexHull h = convex_hull(p);
  EXPECT_NEAR(area(p, h), 2, 1e-12);
  EXPECT_EQ(h.vertices.size(), p.size());  // every point, a superset of the extremes
}

TEST(ConvexHull, SingleTriangle) {
  const std::vector<Vec3> p = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  EXPECT_NEAR(area(p, convex_hull(p)), 2, 1e-12);
}

TEST(ConvexHull, CollinearAndCoincidentPointsHaveNoArea) {
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}};
  const ConvexHull h = convex_hull(line);
  EXPECT_TRUE(h.triangles.empty());
  EXPECT_TRUE(has(h, 0) && has(h, 2));
  const std::vector<Vec3> point = {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
  EXPECT_TRUE(convex_hull(point).triangles.empty());
  EXPECT_EQ(convex_hull(point).vertices.size(), 1u);
  EXPECT_TRUE(convex_hull(std::vector<Vec3>{}).vertices.empty());
}

std::vector<std::uint32_t> sorted_vertices(std::span<const Vec3> p) {
  std::vector<std::uint32_t> v = convex_hull(p).vertices;
  std::sort(v.begin(), v.end());
  return v;
}

TEST(ConvexHull, CollinearPointsGiveTheTwoEndsWhereverTheyAre) {
  // The first point lies between the ends: they are points 1 and 2, not 0 and the farthest.
  EXPECT_EQ(sorted_vertices(std::vector<Vec3>{{1, 1, 1}, {0, 0, 0}, {3, 3, 3}}), (std::vector<std::uint32_t>{1, 2}));
  EXPECT_EQ(sorted_vertices(std::vector<Vec3>{{2, -1, 0}, {1, 0, 0}, {0, 1, 0}, {4, -3, 0}, {3, -2, 0}}),
            (std::vector<std::uint32_t>{2, 3}));
  // Along z only, with the ends given last; two coincident points are one.
  EXPECT_EQ(sorted_vertices(std::vector<Vec3>{{5, 5, 0.5}, {5, 5, 0.25}, {5, 5, -1}, {5, 5, 2}}),
            (std::vector<std::uint32_t>{2, 3}));
  EXPECT_EQ(convex_hull(std::vector<Vec3>{{0, 1, 2}, {0, 1, 2}}).vertices.size(), 1u);
  // Far from the origin, where the differences round: still exactly the ends.
  const double big = 0x1p60;
  EXPECT_EQ(sorted_vertices(std::vector<Vec3>{{big + 2048, 1, -big}, {big, 0.5, -big - 1024}, {big + 4096, 1.5, -big + 1024}}),
            (std::vector<std::uint32_t>{1, 2}));
}

TEST(ConvexHull, NearlyCollinearPointsKeepThePointOffTheLine) {
  // The middle point is one ulp off the line: it is a vertex of the (very thin) triangle.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 1, std::nextafter(1.0, 2.0)}, {3, 3, 3}};
  EXPECT_EQ(sorted_vertices(p), (std::vector<std::uint32_t>{0, 1, 2}));
}

// The vertices of the surface, each once.
std::vector<std::uint32_t> surface_vertices(const ConvexHull& h) {
  std::vector<std::uint32_t> v;
  for (const auto& t : h.triangles) v.insert(v.end(), t.begin(), t.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

TEST(FastConvexHull, CubeWithInnerAndFacePoints) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  p.push_back({0.5, 0.5, 0.5});   // inside
  p.push_back({0.5, 0.25, 1});    // on the top face: kept, as no certificate puts it inside
  const ConvexHull h = fast_convex_hull(p);
  EXPECT_NEAR(area(p, h), 6, 1e-12);
  EXPECT_EQ(surface_vertices(h), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_TRUE(has(h, 9));
}

TEST(FastConvexHull, DropsOnlyPointsCertainlyInside) {
  // A tetrahedron and points strictly inside it, and one just outside a face by 2^-40.
  std::vector<Vec3> p = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1, 1, 1}, {0.5, 0.25, 2}, {0.25, 0.25, 0.25}};
  p.push_back({std::ldexp(1.0, -40), 2, 2});  // outside the face x = 0 by 2^-40: not dropped
  const ConvexHull h = fast_convex_hull(p);
  EXPECT_FALSE(has(h, 4));
  EXPECT_FALSE(has(h, 5));
  EXPECT_FALSE(has(h, 6));
  EXPECT_TRUE(has(h, 7));
  for (std::uint32_t v = 0; v < 4; ++v) EXPECT_TRUE(has(h, v));
}

TEST(FastConvexHull, FlatCollinearAndSinglePoints) {
  // A square in a tilted plane, with a point inside: the square covered twice, every point a
  // vertex (flat points are never certified inside).
  const Vec3 u{1, 2, 2}, v{2, 1, -2};  // orthogonal, length 3
  std::vector<Vec3> square;
  for (const auto& [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) square.push_back(double(a) * u + double(b) * v);
  square.push_back(0.5 * u + 0.25 * v);
  const ConvexHull flat = fast_convex_hull(square);
  EXPECT_NEAR(area(square, flat), 2 * 9, 1e-12);
  EXPECT_EQ(surface_vertices(flat), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(flat.vertices.size(), 5u);
  const std::vector<Vec3> line = {{1, 1, 1}, {0, 0, 0}, {3, 3, 3}, {2, 2, 2}};
  const ConvexHull l = fast_convex_hull(line);
  EXPECT_TRUE(l.triangles.empty());
  EXPECT_EQ(l.vertices.size(), 4u);
  EXPECT_EQ(fast_convex_hull(std::vector<Vec3>{{4, 5, 6}}).vertices.size(), 1u);
  EXPECT_TRUE(fast_convex_hull(std::vector<Vec3>{}).vertices.empty());
}

// On random clouds (in a ball, and on a sphere where every point is a vertex) the surface has the
// vertices and area of Qhull's, and every point lies on the inner side of every facet.
TEST(FastConvexHull, AgreesWithQhullOnRandomClouds) {
  std::mt19937_64 random(5);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Vec3> p;
    const int n = 4 + trial * 7;
    for (int i = 0; i < n; ++i) {
      Vec3 x{normal(random), normal(random), normal(random)};
      if (trial % 2) x = (1 / std::sqrt(dot(x, x))) * x;
      p.push_back(Vec3{100, -7, 3} + x);
    }
    const ConvexHull fast = fast_convex_hull(p), qhull = convex_hull(p);
    std::vector<std::uint32_t> b = qhull.vertices;
    std::sort(b.begin(), b.end());
    EXPECT_EQ(surface_vertices(fast), b) << "trial " << trial;
    // Points in the ball are dropped, but for a few near the surface that no certificate covers.
    EXPECT_LE(fast.vertices.size(), b.size() + p.size() / 8 + 1) << "trial " << trial;
    EXPECT_NEAR(area(p, fast), area(p, qhull), 1e-9 * area(p, qhull));
    for (const auto& t : fast.triangles) {
      const Vec3 facet = cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
      for (const Vec3& x : p) EXPECT_LE(dot(facet, x - p[t[0]]), 1e-9 * std::sqrt(dot(facet, facet)));
    }
  }
}

}  // namespace
}  // namespace cc
