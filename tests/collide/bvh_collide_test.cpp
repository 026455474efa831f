#include "collide/bvh_collide.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "collide/procedural_mesh.h"

namespace cc {
namespace {

using Shape = ProceduralMesh::Shape;
using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

Mat3 rotation(double a, double b, double c) {
  const auto about = [](int axis, double angle) {
    const double co = std::cos(angle), si = std::sin(angle);
    Mat3 m;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    m(i, i) = co, m(i, j) = -si, m(j, i) = si, m(j, j) = co;
    return m;
  };
  const Mat3 x = about(0, a), y = about(1, b), z = about(2, c);
  Mat3 yx, r;
  for (int k = 0; k < 3; ++k) yx.col[k] = y * x.col[k];
  for (int k = 0; k < 3; ++k) r.col[k] = z * yx.col[k];
  return r;
}

Mesh square(double z) {  // the unit square [0, 1]^2 at height z, two triangles
  Mesh m;
  m.vertices = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

template <class BV>
class BvhCollideTest : public ::testing::Test {};
using VolumeTypes = ::testing::Types<Aabb, Obb, Kdop<6>, Kdop<14>, Kdop<16>, Kdop<18>, Kdop<24>, Kdop<26>, Sphere>;
TYPED_TEST_SUITE(BvhCollideTest, VolumeTypes);

const std::vector<RigidTransform> kPoses = {
    {Mat3::identity(), {0, 0, 0}},
    {rotation(0.3, -1.2, 2.0), {0.4, 0.1, -0.2}},
    {rotation(3.0, 0.5, -0.7), {1.1, -0.6, 0.3}},
    {rotation(-2.2, 2.9, 0.1), {1.9, 0.2, 0.0}},
    {rotation(1.0, 1.0, 1.0), {5, 5, 5}},  // apart
};

TYPED_TEST(BvhCollideTest, EveryBuildAndOptionFindsTheBruteForcePairs) {
  const Mesh torus = make_mesh({Shape::torus, 0, 6, 1.0});
  const Mesh soup = make_mesh({Shape::soup, 11, 80, 1.0, 0, 15});
  const RigidTransform place_torus{rotation(0.2, 0.1, 0.0), {0.1, 0, 0}};
  for (const BuildOptions& build : {BuildOptions{}, BuildOptions{BuildStrategy::top_down, SplitAxis::min_sum, SplitPoint::mean, 4},
                                    BuildOptions{BuildStrategy::bottom_up}, BuildOptions{BuildStrategy::incremental}}) {
    const Bvh<TypeParam> a = build_bvh<TypeParam>(torus, build), b = build_bvh<TypeParam>(soup, build);
    for (const RigidTransform& pose : kPoses) {
      const Pairs expected = collide_brute_force(torus, place_torus, soup, pose);
      for (BvUpdate update : {BvUpdate::approximate, BvUpdate::exact}) {
        for (Descent descent : {Descent::first_model, Descent::larger}) {
          const CollisionResult r = collide(a, place_torus, b, pose, {CollisionMode::all_pairs, update, descent});
          EXPECT_EQ(r.pairs, expected);
          EXPECT_LE(r.counters.primitive_tests, torus.size() * soup.size());
          EXPECT_GE(r.counters.bv_tests, 1u);
          if constexpr (std::is_same_v<TypeParam, Obb>) {
            EXPECT_EQ(r.counters.bv_updates, 0u);
          }
          const CollisionResult first = collide(a, place_torus, b, pose, {CollisionMode::first_hit, update, descent});
          ASSERT_EQ(first.pairs.size(), expected.empty() ? 0u : 1u);
          if (!expected.empty()) {
            EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), first.pairs[0]));
          }
          EXPECT_LE(first.counters.primitive_tests, r.counters.primitive_tests);
        }
      }
    }
  }
}

TYPED_TEST(BvhCollideTest, SwappingTheModelsTransposesThePairs) {
  const Mesh sphere = make_mesh({Shape::sphere, 0, 5, 1.0});
  const Mesh plate = make_mesh({Shape::plate, 0, 4, 1.2, 0.01});
  const Bvh<TypeParam> s = build_bvh<TypeParam>(sphere, {}), p = build_bvh<TypeParam>(plate, {});
  const RigidTransform a{rotation(0.1, 0.2, 0.3), {0, 0, 0.2}}, b{rotation(-0.5, 0.4, 0.0), {0.3, 0, 0}};
  Pairs forward = collide(s, a, p, b, {}).pairs, backward = collide(p, b, s, a, {}).pairs;
  ASSERT_FALSE(forward.empty());
  for (auto& [i, j] : backward) std::swap(i, j);
  std::sort(backward.begin(), backward.end());
  EXPECT_EQ(forward, backward);
}

TYPED_TEST(BvhCollideTest, TouchingSquaresCollideAndApartOnesDoNot) {
  const Mesh lower = square(0);
  const Bvh<TypeParam> a = build_bvh<TypeParam>(lower, {});
  const Bvh<TypeParam> b = build_bvh<TypeParam>(square(0), {});
  // b lifted to touch a edge to edge (standing up), then lifted a little further.
  const RigidTransform standing{rotation(M_PI / 2, 0, 0), {0, 0, 0}};
  EXPECT_FALSE(collide(a, {}, b, standing, {}).pairs.empty());
  const RigidTransform above{Mat3::identity(), {0, 0, 1e-6}};
  EXPECT_TRUE(collide(a, {}, b, above, {}).pairs.empty());
  EXPECT_EQ(collide(a, {}, b, {}, {}).pairs.size(), 4u);  // coplanar and overlapping: every pair
}

TYPED_TEST(BvhCollideTest, AMeshInsideAnotherDoesNotCollide) {
  const Mesh big = make_mesh({Shape::sphere, 0, 6, 10.0}), small = make_mesh({Shape::sphere, 0, 4, 1.0});
  const Bvh<TypeParam> a = build_bvh<TypeParam>(big, {}), b = build_bvh<TypeParam>(small, {});
  EXPECT_TRUE(collide(a, {}, b, {}, {}).pairs.empty());
}

TYPED_TEST(BvhCollideTest, MovedVolumesHoldTheMovedTriangles) {
  const Mesh soup = make_mesh({Shape::soup, 5, 40, 100.0, 0, 10});
  const Bvh<TypeParam> b = build_bvh<TypeParam>(soup, {BuildStrategy::top_down, SplitAxis::splatter, SplitPoint::mean, 2});
  const RigidTransform t{rotation(0.7, -0.3, 2.2), {1000, -20, 3}};
  for (BvUpdate update : {BvUpdate::approximate, BvUpdate::exact}) {
    for (std::size_t n = 0; n < b.nodes.size(); ++n) {
      const TypeParam v = moved_volume(b, n, t, update);
      // A degenerate moved triangle inside it overlaps it (checked with the library's own test).
      for (std::uint32_t s = b.nodes[n].first; s < b.nodes[n].first + b.nodes[n].count; ++s) {
        for (const Vec3& p : b.triangle(s).v) {
          const Vec3 q = apply(t, p);
          const std::vector<Vec3> point{q};
          if constexpr (std::is_same_v<TypeParam, Obb>) {
            EXPECT_TRUE(test_obb_obb(v, Obb{q, {0, 0, 0}, Mat3::identity()}));
          } else {
            EXPECT_TRUE(BoundingVolume<TypeParam>::overlap(v, BoundingVolume<TypeParam>::fit(point)));
          }
        }
      }
    }
  }
}

TEST(BvhCollideUpdate, TheExactRefitIsNoLooserThanTheApproximation) {
  const Mesh torus = make_mesh({Shape::torus, 0, 8, 3.0});
  const Bvh<Kdop<18>> b = build_bvh<Kdop<18>>(torus, {BuildStrategy::top_down, SplitAxis::splatter, SplitPoint::mean, 4});
  const RigidTransform t{rotation(0.9, 0.4, -1.3), {2, 0, 0}};
  double exact_width = 0, approximate_width = 0;
  for (std::size_t n = 0; n < b.nodes.size(); ++n) {
    const Kdop<18> e = moved_volume(b, n, t, BvUpdate::exact), a = moved_volume(b, n, t, BvUpdate::approximate);
    for (int i = 0; i < 9; ++i) {
      EXPECT_LE(e.hi[i] - e.lo[i], a.hi[i] - a.lo[i] + 1e-12);
      exact_width += e.hi[i] - e.lo[i], approximate_width += a.hi[i] - a.lo[i];
    }
  }
  EXPECT_LT(exact_width, approximate_width);
}

// Hill climbing finds the exact update's volume of every node, over the frames of a coherent
// motion, at rotations by quarter turns (ties between hull points everywhere) and near them,
// far from the origin, on flat and curved meshes, and from any start.
template <class BV>
void expect_hill_climbing_finds_the_exact_volumes() {
  const Mat3 quarter_turn = Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1});
  std::vector<RigidTransform> poses = {{Mat3::identity(), {0, 0, 0}},
                                       {quarter_turn, {1, 2, 3}},
                                       {rotation(1e-9, 0, 0), {0, 0, 0}},
                                       {rotation(0, -1e-13, 3e-12), {1e3, 0, 0}},
                                       {rotation(0.7, -0.3, 2.2), {-40, 20, 3}}};
  for (int f = 0; f < 24; ++f) poses.push_back({rotation(0.05 * f, 0.03 * f, -0.02 * f), {0.1 * f, 0, 0}});
  for (const ProceduralMesh& recipe : {ProceduralMesh{Shape::torus, 0, 10, 3.0}, ProceduralMesh{Shape::sphere, 0, 8, 1.0},
                                       ProceduralMesh{Shape::plate, 0, 4, 2.0, 0.0}, ProceduralMesh{Shape::plate, 0, 4, 2.0, 0.1},
                                       ProceduralMesh{Shape::terrain, 3, 6, 5.0}, ProceduralMesh{Shape::soup, 5, 60, 10.0, 0, 8}}) {
    const Mesh mesh = make_mesh(recipe);
    for (int leaf_size : {2, 16}) {
      BuildOptions options{BuildStrategy::top_down, SplitAxis::longest_side, SplitPoint::median, leaf_size};
      options.hull_graphs = true;
      const Bvh<BV> b = build_bvh<BV>(mesh, options);
      ASSERT_EQ(b.hull_graphs.walkable.size(), b.nodes.size());
      for (const RigidTransform& t : poses) {
        for (std::size_t n = 0; n < b.nodes.size(); ++n) {
          const BV hill = moved_volume(b, n, t, BvUpdate::hill_climbing), exact = moved_volume(b, n, t, BvUpdate::exact);
          ASSERT_TRUE(hill == exact) << "node " << n << " of a mesh of shape " << static_cast<int>(recipe.shape);
        }
        const RigidTransform place{rotation(0.2, 0.1, 0.0), {0.5, 0, 0}};
        const CollisionResult h = collide(b, place, b, t, {CollisionMode::all_pairs, BvUpdate::hill_climbing, Descent::larger});
        const CollisionResult e = collide(b, place, b, t, {CollisionMode::all_pairs, BvUpdate::exact, Descent::larger});
        EXPECT_EQ(h.pairs, e.pairs);
        EXPECT_EQ(h.counters.bv_tests, e.counters.bv_tests);
        EXPECT_EQ(e.counters.climbed, 0u);
      }
      // Any start will do.
      for (std::uint32_t& s : b.hull_graphs.start) s = s * 7 + 3;
      for (std::size_t n = 0; n < b.nodes.size(); ++n) {
        EXPECT_TRUE(moved_volume(b, n, poses.back(), BvUpdate::hill_climbing) == moved_volume(b, n, poses.back(), BvUpdate::exact));
      }
    }
  }
}

TEST(BvhCollideUpdate, HillClimbingFindsTheExactVolumes) {
  expect_hill_climbing_finds_the_exact_volumes<Aabb>();
  expect_hill_climbing_finds_the_exact_volumes<Kdop<14>>();
  expect_hill_climbing_finds_the_exact_volumes<Kdop<18>>();
  expect_hill_climbing_finds_the_exact_volumes<Kdop<26>>();
}

// A frustum whose wide end, a rim of 48 points in the plane x = 1, is turned from the x axis by
// less than 2^-49: the rim's values along x differ by about the rounding of the walk's values and
// of the moved points, so their orders disagree; the plateau must hold the whole rim.
template <class BV>
void expect_hill_climbing_gathers_near_ties() {
  Mesh cone;
  const int rim = 48;
  for (int end = 0; end < 2; ++end) {
    for (int i = 0; i < rim; ++i) {
      const double angle = 2 * M_PI * i / rim, radius = end == 0 ? 3 : 2;
      cone.vertices.push_back({end == 0 ? 1.0 : -1.0, radius * std::cos(angle), radius * std::sin(angle)});
    }
  }
  for (std::uint32_t i = 0; i < rim; ++i) {
    const std::uint32_t j = (i + 1) % rim;
    cone.faces.push_back({i, j, rim + i});
    cone.faces.push_back({rim + i, j, rim + j});
  }
  BuildOptions options{BuildStrategy::top_down, SplitAxis::longest_side, SplitPoint::median, 96};
  options.hull_graphs = true;
  const Bvh<BV> b = build_bvh<BV>(cone, options);
  std::uint64_t climbed = 0;
  for (int k = 0; k < 200; ++k) {
    const double a = 0x1p-50 * std::sin(1.7 * k), c = 0x1p-50 * std::cos(2.3 * k);
    const RigidTransform t{rotation(0, a, c), {k % 2 == 0 ? 0.0 : 0.75, 0, 0}};
    ASSERT_TRUE(moved_volume(b, 0, t, BvUpdate::hill_climbing) == moved_volume(b, 0, t, BvUpdate::exact)) << "pose " << k;
    climbed += collide(b, {}, b, t, {CollisionMode::first_hit, BvUpdate::hill_climbing, Descent::first_model}).counters.climbed;
  }
  EXPECT_GT(climbed, 100u);  // the walks are certified: the rim is a plateau, not a reason to give up
}

TEST(BvhCollideUpdate, HillClimbingGathersNearTies) {
  expect_hill_climbing_gathers_near_ties<Aabb>();
  expect_hill_climbing_gathers_near_ties<Kdop<18>>();
}

// Where every node has more than 4 k hull points (a sphere in leaves of 256 triangles, turned
// so that no hull has a face of many points, whose ties would make a plateau too large), every
// update of a coherent motion is found by certified walks, each of them short.
TEST(BvhCollideUpdate, HillClimbingCertifiesTheWalksOfLargeNodes) {
  Mesh sphere = make_mesh({Shape::sphere, 0, 32, 3.0});
  const Mat3 turn = rotation(0.4, 0.7, 1.1);
  for (Vec3& v : sphere.vertices) v = turn * v;
  BuildOptions options{BuildStrategy::top_down, SplitAxis::longest_side, SplitPoint::median, 256};
  options.hull_graphs = true;
  const Bvh<Kdop<18>> b = build_bvh<Kdop<18>>(sphere, options);
  for (const auto& [first, count] : b.hull_points.range) ASSERT_GT(count, 72u);
  for (int f = 0; f < 20; ++f) {
    const RigidTransform t{rotation(0.3 + 0.01 * f, 0.02 * f, 0), {0.5, 0.2, 0}};
    const CollisionResult r = collide(b, {}, b, t, {CollisionMode::all_pairs, BvUpdate::hill_climbing, Descent::larger});
    EXPECT_EQ(r.counters.climbed, r.counters.bv_updates) << "frame " << f;
    if (f > 0) {
      EXPECT_LT(r.counters.update_points, 18 * 16 * r.counters.bv_updates) << "frame " << f;  // 16 per walk
    }
  }
}

TEST(BvhCollideNames, Options) {
  EXPECT_EQ(to_string(BvUpdate::hill_climbing), "hill_climbing");
  EXPECT_EQ(to_string(CollisionMode::first_hit), "first_hit");
  EXPECT_EQ(to_string(BvUpdate::exact), "exact");
  EXPECT_EQ(to_string(Descent::larger), "larger");
}

}  // namespace
}  // namespace cc
