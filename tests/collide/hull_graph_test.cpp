#include "collide/hull_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace cc {
namespace {

// Integer coordinates and integer directions: every value m . p below is exact in doubles, so a
// walk's comparisons are exact and its end can be checked against the maximum bit for bit.
double value(const Vec3& m, const Vec3& p) { return m.x * p.x + m.y * p.y + m.z * p.z; }

// Along many directions, every point not highest over the input has a higher neighbour (so
// every climbing walk ends at the maximum, and from every point a climbing path leads there), and
// the highest point over the graph is the highest over the input.
void expect_walks_reach_the_maximum(const std::vector<Vec3>& input, const HullGraph& g, std::mt19937& random) {
  std::uniform_int_distribution<int> coefficient(-3, 3);
  for (int d = 0; d < 40; ++d) {
    const Vec3 m{double(coefficient(random)), double(coefficient(random)), double(coefficient(random))};
    double highest = -std::numeric_limits<double>::infinity(), highest_on_graph = highest;
    for (const Vec3& p : input) highest = std::max(highest, value(m, p));
    for (std::uint32_t v = 0; v < g.points.size(); ++v) {
      const double at = value(m, g.points[v]);
      highest_on_graph = std::max(highest_on_graph, at);
      if (at == highest) continue;
      const auto n = g.neighbours_of(v);
      ASSERT_TRUE(std::any_of(n.begin(), n.end(), [&](std::uint32_t u) { return value(m, g.points[u]) > at; }))
          << "point " << v << " is stuck along " << m.x << " " << m.y << " " << m.z;
    }
    ASSERT_EQ(highest_on_graph, highest);
  }
}

TEST(HullGraph, ACubeWithPointsInsideAndOnItsFacesKeepsItsCornersOnly) {
  std::vector<Vec3> points = {{1, 1, 1}, {0, 0, 0}, {2, 2, 2}, {1, 0, 1}, {1, 2, 1}};  // inside and on faces first
  for (int i = 0; i < 8; ++i) points.push_back({2.0 * (i & 1), 2.0 * ((i >> 1) & 1), 2.0 * (i >> 2)});
  points.push_back({0, 0, 0});  // a repeat
  const auto g = hull_graph(points);
  ASSERT_TRUE(g);
  // (0,0,0) and (2,2,2) are corners too; the face centres and the centre are gone, unless the
  // first tetrahedron took a point on a face (then it stays, on the boundary).
  for (const Vec3& p : g->points) {
    EXPECT_TRUE(p.x == 0 || p.x == 2 || p.y == 0 || p.y == 2 || p.z == 0 || p.z == 2) << "inside: " << p.x << p.y << p.z;
  }
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{2.0 * (i & 1), 2.0 * ((i >> 1) & 1), 2.0 * (i >> 2)};
    EXPECT_EQ(std::count(g->points.begin(), g->points.end(), corner), 1);
  }
  EXPECT_EQ(std::count(g->points.begin(), g->points.end(), Vec3{1, 1, 1}), 0);
  for (std::uint32_t v = 0; v < g->points.size(); ++v) EXPECT_GE(g->neighbours_of(v).size(), 3u);
  std::mt19937 random(1);
  expect_walks_reach_the_maximum(points, *g, random);
}

TEST(HullGraph, RandomIntegerPointsOnGridsPlanesAndLines) {
  std::mt19937 random(7);
  int flat = 0, full = 0, collinear = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::uniform_int_distribution<int> coordinate(-4, 4), count(1, 60), kind(0, 5);
    const int shape = kind(random);
    std::vector<Vec3> points;
    const int n = count(random);
    for (int i = 0; i < n; ++i) {
      const double a = coordinate(random), b = coordinate(random), c = coordinate(random);
      switch (shape) {
        case 0: points.push_back({a, b, 0}); break;           // a plane of the axes
        case 1: points.push_back({a, b, 7 - a - b}); break;   // a tilted plane
        case 2: points.push_back({a, 2 * a + 1, -a}); break;  // a line
        case 3: points.push_back({a, b, c * c}); break;       // coplanar faces and ties
        default: points.push_back({a, b, c}); break;          // a grid: many coplanar faces
      }
    }
    const auto g = hull_graph(points);
    ASSERT_TRUE(g);
    ASSERT_EQ(g->offsets.size(), g->points.size() + 1);
    std::size_t most = 0;
    for (std::uint32_t v = 0; v < g->points.size(); ++v) most = std::max(most, g->neighbours_of(v).size());
    if (shape <= 1 && g->points.size() >= 3) {
      ++flat;
      EXPECT_EQ(most, 2u);  // a polygon
    } else if (shape == 2) {
      ++collinear;
      EXPECT_LE(g->points.size(), 2u);
    } else if (most > 2) {
      ++full;
      // A triangulated sphere: E = 3V - 6 (no facet missing, none twice or overlapping).
      EXPECT_EQ(g->neighbours.size(), 2 * (3 * g->points.size() - 6));
    }
    expect_walks_reach_the_maximum(points, *g, random);
  }
  EXPECT_GT(flat, 50);
  EXPECT_GT(collinear, 20);
  EXPECT_GT(full, 100);
}

TEST(HullGraph, APolygonKeepsOnlyItsCornersNotThePointsOnItsEdges) {
  const std::vector<Vec3> points = {{1, 0, 5}, {0, 0, 5}, {2, 0, 5}, {2, 1, 5}, {2, 2, 5}, {0, 2, 5}, {1, 1, 5}};
  const auto g = hull_graph(points);
  ASSERT_TRUE(g);
  const std::vector<Vec3> corners = {{0, 0, 5}, {2, 0, 5}, {2, 2, 5}, {0, 2, 5}};
  EXPECT_EQ(g->points, corners);  // in input order
  for (std::uint32_t v = 0; v < 4; ++v) EXPECT_EQ(g->neighbours_of(v).size(), 2u);
}

TEST(HullGraph, FewPointsAndBadOnes) {
  EXPECT_TRUE(hull_graph({})->points.empty());
  const Vec3 one[] = {{1, 2, 3}, {1, 2, 3}};
  const auto single = hull_graph(one);
  ASSERT_TRUE(single);
  EXPECT_EQ(single->points.size(), 1u);
  EXPECT_TRUE(single->neighbours_of(0).empty());
  const Vec3 line[] = {{0, 0, 0}, {3, 3, 3}, {1, 1, 1}, {-1, -1, -1}};
  const auto segment = hull_graph(line);
  ASSERT_TRUE(segment);
  EXPECT_EQ(segment->points, (std::vector<Vec3>{{3, 3, 3}, {-1, -1, -1}}));
  EXPECT_EQ(segment->neighbours_of(0).size(), 1u);
  const Vec3 bad[] = {{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}};
  EXPECT_FALSE(hull_graph(bad));
  const Vec3 infinite[] = {{0, 0, 0}, {INFINITY, 0, 0}};
  EXPECT_FALSE(hull_graph(infinite));
}

TEST(HullGraph, NearlyCoplanarPointsAreDecidedExactly) {
  // A square and a point above its centre by one unit in the last place of 2^20: the float
  // determinant cannot see it, the exact one keeps it (it is a vertex of the pyramid).
  const double h = 0x1p20;
  const std::vector<Vec3> points = {{h, h, h}, {h + 1, h, h}, {h + 1, h + 1, h}, {h, h + 1, h},
                                    {h + 0.5, h + 0.5, std::nextafter(h, INFINITY)}};
  const auto g = hull_graph(points);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->points.size(), 5u);
  EXPECT_EQ(g->neighbours_of(4).size(), 4u);
  // Exactly on the square's plane, the centre is dropped: the hull is the square.
  std::vector<Vec3> flat = points;
  flat[4].z = h;
  const auto square = hull_graph(flat);
  ASSERT_TRUE(square);
  EXPECT_EQ(square->points.size(), 4u);
}

}  // namespace
}  // namespace cc
