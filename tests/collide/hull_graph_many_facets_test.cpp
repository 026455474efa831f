// Rare configurations reached on purpose: hulls that need many facet replacements. Every point
// of each set is a vertex of its hull (points of a paraboloid, of a sphere, of the moment curve),
// so every point is added and replaces facets; they are fed outward (each point beyond the hull
// of the earlier ones) and reversed, though quickhull picks its own order. Points that see more
// than 16 facets at once occur: the mutant hull_graph.visible_flood_stops_at_16 fails here (the
// API exposes no count of replacements). The paraboloid's and the sphere's integer points also
// lie by fours and more on common circles, so the hull has planar faces of many points; each set
// is also scaled to 2^-1040 (subnormal coordinates) and 2^200. Checked with exact orientation
// signs (exact_orientation.h): hull_graph keeps exactly the input points, its graph is a
// triangulated sphere (3n - 6 edges, so 2n - 4 triangles: many facets), every edge lies in two
// triangles of the graph whose planes support every input point (each input point is inside
// the hull or on it), and a walk that climbs a linear function ends only at its maximum.
#include "collide/hull_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "collide/exact_orientation.h"
#include "test_random.h"

namespace cc {
namespace {

bool less(const Vec3& a, const Vec3& b) { return std::array{a.x, a.y, a.z} < std::array{b.x, b.y, b.z}; }

// Points (x, y, x^2 + y^2) for integer x^2 + y^2 <= r^2, by increasing x^2 + y^2.
std::vector<Vec3> paraboloid(int r) {
  std::vector<Vec3> p;
  for (int x = -r; x <= r; ++x) {
    for (int y = -r; y <= r; ++y) {
      if (x * x + y * y <= r * r) p.push_back({double(x), double(y), double(x * x + y * y)});
    }
  }
  std::stable_sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return a.z < b.z; });
  return p;
}

// The integer points of the sphere x^2 + y^2 + z^2 = n, by increasing z (a sweep from a pole).
std::vector<Vec3> sphere(int n) {
  std::vector<Vec3> p;
  const int r = static_cast<int>(std::sqrt(double(n)));
  for (int x = -r; x <= r; ++x) {
    for (int y = -r; y <= r; ++y) {
      const int zz = n - x * x - y * y;
      if (zz < 0) continue;
      const int z = static_cast<int>(std::lround(std::sqrt(double(zz))));
      if (z * z != zz) continue;
      p.push_back({double(x), double(y), double(z)});
      if (z != 0) p.push_back({double(x), double(y), double(-z)});
    }
  }
  std::stable_sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return a.z < b.z; });
  return p;
}

// (t, t^2, t^3) for t = -m .. m, by increasing |t| (the cyclic polytope: no four coplanar).
std::vector<Vec3> moment_curve(int m) {
  std::vector<Vec3> p;
  for (int k = 0; k <= m; ++k) {
    for (int t : {k, -k}) {
      p.push_back({double(t), double(t) * t, double(t) * t * t});
      if (k == 0) break;
    }
  }
  return p;
}

std::vector<Vec3> scaled(std::vector<Vec3> p, int k, const Vec3& offset) {
  for (Vec3& v : p) v = {std::ldexp(v.x + offset.x, k), std::ldexp(v.y + offset.y, k), std::ldexp(v.z + offset.z, k)};
  return p;
}

struct Checked {
  int points = 0, triangles = 0, coplanar_triangles = 0;
};

// The checks of the header on one set of points, all of them vertices of their hull.
void check(const std::string& name, const std::vector<Vec3>& input, Checked& met, bool integers = true) {
  SCOPED_TRACE(name);
  const std::optional<HullGraph> graph = hull_graph(input);
  ASSERT_TRUE(graph.has_value());
  const std::size_t n = input.size();
  // Exactly the input points, each once.
  std::vector<Vec3> said = graph->points, given = input;
  std::sort(said.begin(), said.end(), less);
  std::sort(given.begin(), given.end(), less);
  ASSERT_EQ(said.size(), n);
  ASSERT_TRUE(said == given) << "the hull's points are not the input points (all of them vertices of the hull)";
  ASSERT_EQ(graph->offsets.size(), n + 1);
  // A triangulated sphere: symmetric, simple, 3n - 6 edges.
  std::vector<std::vector<std::uint32_t>> adjacent(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t k = graph->offsets[i]; k < graph->offsets[i + 1]; ++k) adjacent[i].push_back(graph->neighbours[k]);
    std::sort(adjacent[i].begin(), adjacent[i].end());
    ASSERT_TRUE(std::adjacent_find(adjacent[i].begin(), adjacent[i].end()) == adjacent[i].end());
    ASSERT_FALSE(std::binary_search(adjacent[i].begin(), adjacent[i].end(), i));
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j : adjacent[i]) ASSERT_TRUE(std::binary_search(adjacent[j].begin(), adjacent[j].end(), i));
  }
  ASSERT_EQ(graph->neighbours.size(), 2 * (3 * n - 6));
  // Every edge in two triangles of the graph whose planes have every input point on one side
  // (or on them): so every input point is inside the hull or on it.
  const std::vector<Vec3>& p = graph->points;
  int triangles = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j : adjacent[i]) {
      if (j < i) continue;
      int supporting = 0;
      for (std::uint32_t k : adjacent[i]) {
        if (k == j || !std::binary_search(adjacent[j].begin(), adjacent[j].end(), k)) continue;
        bool above = false, below = false;
        int on = 0;
        for (const Vec3& q : input) {
          const int s = *orientation_sign(p[i], p[j], p[k], q);
          above |= s > 0, below |= s < 0, on += s == 0;
        }
        if (above && below) continue;
        ASSERT_TRUE(above || below) << "a triangle of the graph with every point in its plane";
        ++supporting;
        if (k > j) ++triangles, met.coplanar_triangles += on > 3;
      }
      ASSERT_GE(supporting, 2) << "the edge " << i << "-" << j << " is not on two supporting triangles";
    }
  }
  ASSERT_GE(triangles, static_cast<int>(2 * n - 4));
  // Climbing: at a point that is not highest, a neighbour is higher (integer directions and
  // coordinates: the dot products are exact where the coordinates are integers below 2^30).
  test::Random random(n);
  for (int d = 0; d < (integers ? 8 : 0); ++d) {
    const Vec3 dir{double(random.in(-1000, 1000)), double(random.in(-1000, 1000)), double(random.in(-1000, 1000))};
    const auto height = [&](const Vec3& v) { return dot(dir, v); };
    double top = -INFINITY;
    for (const Vec3& q : input) top = std::max(top, height(q));
    for (std::uint32_t i = 0; i < n; ++i) {
      if (height(p[i]) == top) continue;
      ASSERT_TRUE(std::any_of(adjacent[i].begin(), adjacent[i].end(), [&](std::uint32_t j) { return height(p[j]) > height(p[i]); }))
          << "a climbing walk stops below the top at point " << i;
    }
  }
  met.points += static_cast<int>(n);
  met.triangles += triangles;
}

TEST(HullGraphManyFacets, PointsAllOnTheHullAddedOutwardGiveATriangulatedSphereOfSupportingFacets) {
  Checked met;
  const std::vector<std::pair<std::string, std::vector<Vec3>>> sets = {
      {"paraboloid r 12", paraboloid(12)},
      {"paraboloid r 12 far from the origin", scaled(paraboloid(12), 0, {1 << 20, -(1 << 20), 1 << 21})},
      {"sphere 2 * 5^2 * 13", sphere(650)},
      {"sphere 5^2 * 13 * 17", sphere(5525)},
      {"moment curve 150", moment_curve(150)},
  };
  for (const auto& [name, points] : sets) {
    ASSERT_GE(points.size(), 150u) << name;
    check(name, points, met);
    // The same at a scale within 2^-1000 of the subnormal range, and near the top of the range,
    // and fed in the opposite order.
    if (name.starts_with("moment")) continue;  // its coordinates reach 2^22: 2^-1000 of them would round
    check(name + " at 2^-1040", scaled(points, -1040, {}), met, false);
    check(name + " at 2^200", scaled(points, 200, {}), met, false);
    std::vector<Vec3> reversed(points.rbegin(), points.rend());
    check(name + " reversed", reversed, met);
  }
  std::printf("hull graph: %d points, %d supporting triangles (%d in a plane with more than 3 points)\n", met.points,
              met.triangles, met.coplanar_triangles);
  EXPECT_GT(met.triangles, 15000);
  EXPECT_GT(met.coplanar_triangles, 8000);
}

}  // namespace
}  // namespace cc
