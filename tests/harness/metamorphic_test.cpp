#include "harness/metamorphic.h"

#include <gtest/gtest.h>
#include "test_paths.h"

#include "harness/choices.h"
#include "harness/generate.h"
#include "harness/input_json.h"

namespace cc::harness {
namespace {

std::string text(const Input& in) { return input_to_json(in).dump(); }

TEST(Transform, FlippingOrSwappingTwiceIsTheIdentity) {
  for (QueryKind kind : kAllQueryKinds) {
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
      RandomChoices c(seed);
      const Input in = generate(kind, c, {.mesh_folder = test::fcl_mesh_folder()});
      for (int axis = 0; axis < 3; ++axis) {
        const auto once = transform(in, Relation::flip_axis, axis);
        if (!once) continue;
        EXPECT_EQ(text(*transform(*once, Relation::flip_axis, axis)), text(in)) << name(kind);
      }
      if (const auto swapped = transform(in, Relation::swap_shapes, 0)) {
        EXPECT_EQ(text(*transform(*swapped, Relation::swap_shapes, 0)), text(in));
      }
    }
  }
}

TEST(Transform, ScalingUpAndDownIsTheIdentityOrDoesNotApply) {
  for (QueryKind kind : kAllQueryKinds) {
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
      RandomChoices c(seed);
      const Input in = flush_extremes(generate(kind, c, {.mesh_folder = test::fcl_mesh_folder()}));
      const auto up = transform(in, Relation::scale, 5);
      if (!relation_applies(kind, Relation::scale)) {
        EXPECT_FALSE(up.has_value());
        continue;
      }
      ASSERT_TRUE(up.has_value()) << name(kind) << " " << text(in);
      EXPECT_EQ(text(*transform(*up, Relation::scale, -5)), text(in));
    }
  }
  // 2^-1074 cannot be halved exactly: the relation does not apply.
  EXPECT_FALSE(transform(SphereSphereInput{{{5e-324, 0, 0}, 1}, {{0, 0, 0}, 1}}, Relation::scale, -1).has_value());
}

TEST(Transform, PermutingAxesMovesCoordinates) {
  const Input in = AabbAabbInput{{{1, 2, 3}, {4, 5, 6}}, {{0, 0, 0}, {1, 1, 1}}};
  const auto p = transform(in, Relation::permute_axes, 3);  // {1, 2, 0}: x' = y, y' = z, z' = x
  ASSERT_TRUE(p);
  EXPECT_EQ(std::get<AabbAabbInput>(*p).a.lo, (Vec3{2, 3, 1}));
}

TEST(Transform, KdopDirectionSetsNotClosedAreSkipped) {
  const Input k16 = KdopKdopInput{16, {{0, 0, 0}}, {{1, 1, 1}}};
  const Input k24 = KdopKdopInput{24, {{0, 0, 0}}, {{1, 1, 1}}};
  EXPECT_FALSE(transform(k16, Relation::permute_axes, 1));
  EXPECT_FALSE(transform(k16, Relation::flip_axis, 0));
  EXPECT_TRUE(transform(k24, Relation::permute_axes, 1));
  EXPECT_FALSE(transform(k24, Relation::flip_axis, 0));
  EXPECT_TRUE(transform(KdopKdopInput{26, {{0, 0, 0}}, {{1, 1, 1}}}, Relation::flip_axis, 2));
}

TEST(Transform, RaysAndTrianglesAgainstBoxesHaveNothingToSwap) {
  EXPECT_FALSE(transform(RayAabbInput{}, Relation::swap_shapes, 0));
  EXPECT_FALSE(transform(TriObbInput{}, Relation::swap_shapes, 0));
  EXPECT_TRUE(transform(TriTriInput{}, Relation::swap_shapes, 0));
}

TEST(FlushExtremes, ZeroesTinyAndHugeValuesOnly) {
  const Input in = SphereSphereInput{{{0x1p-300, 0x1p260, 3}, 5e-324}, {{-0x1p-250, 0, 0}, 1}};
  const Input flushed = flush_extremes(in);
  const auto& out = std::get<SphereSphereInput>(flushed);
  EXPECT_EQ(out.a.center, (Vec3{0, 0, 3}));
  EXPECT_EQ(out.a.radius, 0);
  EXPECT_EQ(out.b.center.x, -0x1p-250);
}

}  // namespace
}  // namespace cc::harness
