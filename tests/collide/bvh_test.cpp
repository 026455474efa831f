#include "collide/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "collide/procedural_mesh.h"

namespace cc {
namespace {

using Shape = ProceduralMesh::Shape;

template <class BV>
class BvhTest : public ::testing::Test {};
using VolumeTypes = ::testing::Types<Aabb, Obb, Kdop<6>, Kdop<14>, Kdop<16>, Kdop<18>, Kdop<24>, Kdop<26>, Sphere>;
TYPED_TEST_SUITE(BvhTest, VolumeTypes);

std::vector<BuildOptions> every_build() {
  std::vector<BuildOptions> out;
  for (SplitAxis axis : {SplitAxis::longest_side, SplitAxis::splatter, SplitAxis::min_sum, SplitAxis::min_max}) {
    for (SplitPoint point : {SplitPoint::midpoint, SplitPoint::mean, SplitPoint::median}) {
      out.push_back({BuildStrategy::top_down, axis, point, axis == SplitAxis::longest_side ? 1 : 3});
    }
  }
  out.push_back({BuildStrategy::bottom_up});
  out.push_back({BuildStrategy::incremental});
  return out;
}

// Whether the volume holds the point, allowing for the rounding of the check itself.
bool holds(const Aabb& b, const Vec3& p) {
  return b.lo.x <= p.x && p.x <= b.hi.x && b.lo.y <= p.y && p.y <= b.hi.y && b.lo.z <= p.z && p.z <= b.hi.z;
}
bool holds(const Obb& b, const Vec3& p) {
  const Vec3 u = transpose_times(b.axes, p - b.center);
  const double slack = 1e-12 * (1 + norm1(p));
  return std::fabs(u.x) <= b.half.x + slack && std::fabs(u.y) <= b.half.y + slack && std::fabs(u.z) <= b.half.z + slack;
}
bool holds(const Sphere& b, const Vec3& p) {
  const Vec3 d = p - b.center;
  return std::sqrt(dot(d, d)) <= b.radius * (1 + 1e-12) + 1e-300;
}
template <int K>
bool holds(const Kdop<K>& d, const Vec3& p) {
  const auto dirs = kdop_directions<K>();
  for (int i = 0; i < K / 2; ++i) {
    const double s = dirs[i].x * p.x + dirs[i].y * p.y + dirs[i].z * p.z, slack = 1e-12 * (1 + norm1(p));
    if (s < d.lo[i] - slack || s > d.hi[i] + slack) return false;
  }
  return true;
}

// Every face in exactly one leaf; children split their parent's slots; volumes hold triangles.
template <class BV>
void expect_well_formed(const Mesh& mesh, const Bvh<BV>& bvh, const BuildOptions& o) {
  SCOPED_TRACE(std::string(to_string(o.strategy)) + " " + std::string(to_string(o.axis)) + " " +
               std::string(to_string(o.point)));
  ASSERT_EQ(bvh.order.size(), mesh.size());
  std::vector<std::uint32_t> sorted = bvh.order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
  ASSERT_EQ(bvh.nodes[0].first, 0u);
  ASSERT_EQ(bvh.nodes[0].count, mesh.size());
  for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
    const BvhNode<BV>& node = bvh.nodes[n];
    if (node.leaf()) {
      const int cap = o.strategy == BuildStrategy::top_down ? std::max(o.leaf_size, 1) : 1;
      EXPECT_LE(node.count, static_cast<std::uint32_t>(cap));
      EXPECT_GE(node.count, 1u);
    } else {
      const auto &l = bvh.nodes[node.left], &r = bvh.nodes[node.right];
      EXPECT_GT(node.left, static_cast<std::int32_t>(n));
      EXPECT_EQ(l.first, node.first);
      EXPECT_EQ(r.first, l.first + l.count);
      EXPECT_EQ(l.count + r.count, node.count);
    }
    for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
      EXPECT_EQ(bvh.triangle(s), mesh.triangle(bvh.order[s]));
      for (const Vec3& v : bvh.triangle(s).v) ASSERT_TRUE(holds(node.bv, v)) << "node " << n << " slot " << s;
    }
  }
}

TYPED_TEST(BvhTest, EveryBuildIsWellFormed) {
  const Mesh torus = make_mesh({Shape::torus, 1, 6, 2.0});
  const Mesh soup = make_mesh({Shape::soup, 7, 60, 3.0, 0, 20});
  for (const BuildOptions& o : every_build()) {
    expect_well_formed(torus, build_bvh<TypeParam>(torus, o), o);
    expect_well_formed(soup, build_bvh<TypeParam>(soup, o), o);
  }
}

TYPED_TEST(BvhTest, EmptyAndSingleTriangleMeshes) {
  EXPECT_TRUE(build_bvh<TypeParam>(Mesh{}, {}).nodes.empty());
  const Mesh one = make_mesh({Shape::soup, 1, 1, 1.0});
  for (const BuildOptions& o : every_build()) {
    const Bvh<TypeParam> b = build_bvh<TypeParam>(one, o);
    ASSERT_EQ(b.nodes.size(), 1u);
    EXPECT_TRUE(b.nodes[0].leaf());
  }
}

TYPED_TEST(BvhTest, IdenticalTrianglesStillSplit) {
  // Every centroid is the same point: no split point separates them, the median fallback does.
  Mesh same = make_mesh({Shape::soup, 3, 1, 1.0});
  for (int i = 0; i < 40; ++i) same.faces.push_back(same.faces[0]);
  for (const BuildOptions& o : every_build()) expect_well_formed(same, build_bvh<TypeParam>(same, o), o);
}

TYPED_TEST(BvhTest, TrianglesAreTheMeshsIndicesInSlotOrderAndArraysAreSizedExactly) {
  // A shared-vertex mesh: the hierarchy keeps the mesh's vertices and, per slot, its face.
  Mesh grid;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) grid.vertices.push_back({double(i), double(j), 0.25 * i * j});
  }
  for (std::uint32_t i = 0; i < 4; ++i) {
    for (std::uint32_t j = 0; j < 4; ++j) {
      grid.faces.push_back({5 * i + j, 5 * i + j + 5, 5 * i + j + 1});
      grid.faces.push_back({5 * i + j + 1, 5 * i + j + 5, 5 * i + j + 6});
    }
  }
  for (const BuildOptions& o : every_build()) {
    const Bvh<TypeParam> b = build_bvh<TypeParam>(grid, o);
    EXPECT_EQ(b.vertices, grid.vertices);
    for (std::size_t s = 0; s < b.faces.size(); ++s) EXPECT_EQ(b.faces[s], grid.faces[b.order[s]]);
    EXPECT_EQ(b.vertices.capacity(), b.vertices.size());
    EXPECT_EQ(b.faces.capacity(), grid.size());
    EXPECT_EQ(b.order.capacity(), grid.size());
    EXPECT_EQ(b.nodes.capacity(), b.nodes.size());
    expect_well_formed(grid, b, o);
  }
}

TYPED_TEST(BvhTest, HullPointsOnlyOnRequestAndOnlyForAabbAndKdopTrees) {
  const Mesh sphere = make_mesh({Shape::sphere, 0, 5, 1.0});
  const Bvh<TypeParam> lean = build_bvh<TypeParam>(sphere, {});
  EXPECT_TRUE(lean.hull_points.points.empty());
  EXPECT_TRUE(lean.hull_points.range.empty());
  BuildOptions o;
  o.hull_points = true;
  const Bvh<TypeParam> b = build_bvh<TypeParam>(sphere, o);
  if constexpr (std::is_same_v<TypeParam, Obb> || std::is_same_v<TypeParam, Sphere>) {  // moved whole, never updated
    EXPECT_TRUE(b.hull_points.points.empty());
  } else {
    ASSERT_EQ(b.hull_points.range.size(), b.nodes.size());
    // The root's hull points are on the sphere (its convex hull's vertices), each once.
    const auto root = b.hull_points.of(0);
    EXPECT_LE(root.size(), 3 * sphere.size());
    EXPECT_GE(root.size(), 4u);
    for (const Vec3& p : root) EXPECT_NEAR(std::sqrt(dot(p, p)), 1.0, 1e-12);
    // A leaf's are its triangle's distinct vertices.
    for (std::size_t n = 0; n < b.nodes.size(); ++n) {
      if (b.nodes[n].leaf()) {
        EXPECT_LE(b.hull_points.of(n).size(), 3u);
      }
    }
  }
  EXPECT_GE(b.magnitude, 1.0);
}

TEST(BvhSplit, LongestSideMidpointSplitsAStripAcrossItsLength) {
  // Ten unit triangles in a row along x: the root splits them into x < 5 and x > 5.
  Mesh strip;
  for (int i = 0; i < 10; ++i) {
    const auto n = static_cast<std::uint32_t>(strip.vertices.size());
    strip.vertices.insert(strip.vertices.end(), {Vec3{double(i), 0, 0}, Vec3{i + 1.0, 0, 0}, Vec3{i + 0.5, 1, 0}});
    strip.faces.push_back({n, n + 1, n + 2});
  }
  const Bvh<Aabb> b = build_bvh<Aabb>(strip, {});
  const auto& left = b.nodes[b.nodes[0].left];
  EXPECT_EQ(left.count, 5u);
  for (std::uint32_t s = left.first; s < left.first + left.count; ++s) EXPECT_LT(b.order[s], 5u);
}

TEST(BvhSplit, NamesOfTheOptions) {
  EXPECT_EQ(to_string(BuildStrategy::incremental), "incremental");
  EXPECT_EQ(to_string(SplitAxis::min_max), "min_max");
  EXPECT_EQ(to_string(SplitPoint::median), "median");
}

}  // namespace
}  // namespace cc
