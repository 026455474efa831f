#include "collide/bvh_lazy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "collide/bvh_collide.h"
#include "collide/procedural_mesh.h"

namespace cc {
namespace {

using Shape = ProceduralMesh::Shape;

Mat3 quarter_turn_about_z() { return Mat3::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}); }

Mat3 tilted() {  // a rotation with no simple entries: about (1, 1, 1) by about 0.6 rad, orthonormal to rounding
  const double c = std::cos(0.6), s = std::sin(0.6), t = 1 - c, k = 1 / std::sqrt(3.0);
  return Mat3::from_columns({t * k * k + c, t * k * k + s * k, t * k * k - s * k},
                            {t * k * k - s * k, t * k * k + c, t * k * k + s * k},
                            {t * k * k + s * k, t * k * k - s * k, t * k * k + c});
}

const std::vector<RigidTransform> kPoses = {
    {Mat3::identity(), {0, 0, 0}},       {tilted(), {0.3, -0.2, 0.1}},
    {quarter_turn_about_z(), {1.2, 0, 0}}, {tilted(), {0.9, 0.7, -0.4}},
    {tilted(), {6, 6, 6}},  // apart
};

template <class BV>
class LazyBvhTest : public ::testing::Test {};
using VolumeTypes = ::testing::Types<Aabb, Kdop<6>, Kdop<14>, Kdop<16>, Kdop<18>, Kdop<24>, Kdop<26>>;
TYPED_TEST_SUITE(LazyBvhTest, VolumeTypes);

// Aabb and k-DOP trees: the lazy walk is the eager walk, counters and all, in every mode.
TYPED_TEST(LazyBvhTest, GivesTheEagerTreesAnswerAndCountsExactly) {
  const Mesh torus = make_mesh({Shape::torus, 0, 6, 1.0});
  const Mesh soup = make_mesh({Shape::soup, 11, 80, 1.0, 0, 15});
  const RigidTransform place_torus{tilted(), {0.1, 0, 0}};
  for (const BuildOptions& build : {BuildOptions{}, BuildOptions{BuildStrategy::top_down, SplitAxis::min_sum, SplitPoint::median, 3},
                                    BuildOptions{BuildStrategy::top_down, SplitAxis::splatter, SplitPoint::mean, 1}}) {
    const Bvh<TypeParam> a = build_bvh<TypeParam>(torus, build), b = build_bvh<TypeParam>(soup, build);
    for (const RigidTransform& pose : kPoses) {
      for (CollisionMode mode : {CollisionMode::all_pairs, CollisionMode::first_hit}) {
        for (BvUpdate update : {BvUpdate::approximate, BvUpdate::exact}) {
          for (Descent descent : {Descent::first_model, Descent::larger}) {
            const CollideOptions options{mode, update, descent};
            LazyBvh<TypeParam> la(torus, build), lb(soup, build);
            const CollisionResult eager = collide(a, place_torus, b, pose, options);
            const CollisionResult lazy = collide(la, place_torus, lb, pose, options);
            EXPECT_EQ(lazy.pairs, eager.pairs);
            EXPECT_EQ(lazy.counters, eager.counters);
            EXPECT_LE(la.nodes_made(), a.nodes.size());
            EXPECT_LE(lb.nodes_made(), b.nodes.size());
            // Asked again, the tree made so far gives the same answer.
            EXPECT_EQ(collide(la, place_torus, lb, pose, options).pairs, eager.pairs);
          }
        }
      }
    }
  }
}

// A node made is the eager tree's node with the same slots, bit for bit.
TYPED_TEST(LazyBvhTest, MadeNodesAreTheEagerTreesNodes) {
  const Mesh terrain = make_mesh({Shape::terrain, 3, 7, 2.0, 0, 10});
  const BuildOptions build{BuildStrategy::top_down, SplitAxis::longest_side, SplitPoint::midpoint, 2};
  const Bvh<TypeParam> eager = build_bvh<TypeParam>(terrain, build);
  LazyBvh<TypeParam> lazy(terrain, build);
  for (std::int32_t n = 0; n < static_cast<std::int32_t>(lazy.nodes_made()); ++n) lazy.split(n);  // all of it
  ASSERT_EQ(lazy.nodes_made(), eager.nodes.size());
  EXPECT_EQ(lazy.tree().order, eager.order);
  EXPECT_EQ(lazy.tree().magnitude, eager.magnitude);
  for (const BvhNode<TypeParam>& n : lazy.tree().nodes) {
    const auto same = std::find_if(eager.nodes.begin(), eager.nodes.end(), [&](const BvhNode<TypeParam>& e) {
      return e.first == n.first && e.count == n.count;
    });
    ASSERT_NE(same, eager.nodes.end());
    EXPECT_TRUE(same->bv == n.bv);
    EXPECT_EQ(same->leaf(), n.leaf());
  }
}

TEST(LazyBvh, APairApartMakesOnlyTheRoots) {
  const Mesh torus = make_mesh({Shape::torus, 0, 8, 1.0});
  LazyBvh<Aabb> a(torus, {}), b(torus, {});
  const CollisionResult r = collide(a, {Mat3::identity(), {0, 0, 0}}, b, {tilted(), {9, 0, 0}}, {});
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_EQ(a.nodes_made(), 1u);
  EXPECT_EQ(b.nodes_made(), 1u);
  EXPECT_EQ(a.tree().nodes[0].left, kNotSplitYet);
}

TEST(LazyBvh, ObbAndSphereTreesFindTheBruteForcePairs) {
  const Mesh torus = make_mesh({Shape::torus, 0, 6, 1.0});
  const Mesh soup = make_mesh({Shape::soup, 11, 80, 1.0, 0, 15});
  const RigidTransform place_torus{tilted(), {0.1, 0, 0}};
  for (const RigidTransform& pose : kPoses) {
    const auto expected = collide_brute_force(torus, place_torus, soup, pose);
    LazyBvh<Obb> oa(torus, {}), ob(soup, {});
    LazyBvh<Sphere> sa(torus, {}), sb(soup, {});
    EXPECT_EQ(collide(oa, place_torus, ob, pose, {}).pairs, expected);
    EXPECT_EQ(collide(sa, place_torus, sb, pose, {}).pairs, expected);
  }
}

TEST(LazyBvh, AnEmptyMeshHasNoNodesAndNoPairs) {
  LazyBvh<Aabb> empty(Mesh{}, {}), torus(make_mesh({Shape::torus, 0, 4, 1.0}), {});
  EXPECT_EQ(empty.nodes_made(), 0u);
  EXPECT_TRUE(collide(empty, {}, torus, {}, {}).pairs.empty());
}

}  // namespace
}  // namespace cc
