#include "collide/bound_records.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc::bounds {
namespace {

TEST(Widening, MovesEveryParameterOutwardAndKeepsInfinities) {
  for (const Widening w : {kRaySlab, kRayTriangleParameter, kRayVolumeEntry, kSweepObbTime, kSweepAabbTime}) {
    for (double t : {-3.5, -1.0, -0x1p-1060, -0.0, 0.0, 0x1p-1074, 0x1p-900, 1.0, 7.25, 0x1p1000}) {
      EXPECT_LT(w.lower(t), t);
      EXPECT_GT(w.upper(t), t);
      // The relative term: t moved by rounding(t) still lies within [lower(t), upper(t)].
      EXPECT_LE(w.lower(t), t - w.rounding(t));
      EXPECT_GE(w.upper(t), t + w.rounding(t));
    }
    EXPECT_EQ(w.lower(INFINITY), INFINITY);
    EXPECT_EQ(w.upper(-INFINITY), -INFINITY);
    EXPECT_EQ(w.rounding(-2.0), 2 * w.relative);
  }
}

TEST(ErrorBounds, TotalsAreTheirTermsAndTheSlack) {
  const SphereBound sphere{3, 2.5};
  EXPECT_EQ(sphere.total(), 8 * fp::u * 5.5);
  EXPECT_EQ(sphere.distance(), 24 * fp::u);

  const ObbBound obb{4, 1, 2};
  EXPECT_EQ(obb.rounding(), 32 * fp::u * 7);
  EXPECT_EQ(obb.frame(), 18 * kObbOrthonormalTolerance);
  EXPECT_EQ(obb.total(), obb.rounding() + obb.frame() + fp::subnormal_slack);
  EXPECT_EQ((ObbBound{4, 0, 0}.frame()), 0);  // points: no frame to be off

  const SatBound sat{2, 1, 3, 0x1p-40};
  EXPECT_EQ(sat.projection(), 2 * 5 * fp::u * 4);
  EXPECT_EQ(sat.perturbation(), 0x1p-39);
  EXPECT_EQ(sat.total(), sat.projection() + sat.perturbation() + fp::subnormal_slack);

  const FrameChangeBound frame{8, 3};
  EXPECT_EQ(frame.total(), 40 * fp::u + 6 * kObbOrthonormalTolerance + fp::subnormal_slack);

  EXPECT_EQ((IndependenceBound{2, 3, 0.5}.rounding()), 48 * fp::u);

  const RayTriangleSlabBound slab{2, 4, 1.5, false};
  EXPECT_EQ(slab.projection_total(), 64 * fp::u + fp::subnormal_slack);
  EXPECT_EQ(slab.speed_total(), 9 * fp::u);
  EXPECT_EQ((RayTriangleSlabBound{2, 4, 1.5, true}.speed_total()), 9 * fp::u + fp::subnormal_slack);

  const RayMeshPad pad{3, 5};
  EXPECT_EQ(pad.total(), pad.origin() + pad.mesh() + fp::subnormal_slack);
  EXPECT_EQ(pad.origin(), 0x1p-40 * 3);

  const TransformBound transform{6, 10};
  EXPECT_EQ(transform.total(), transform.rotation_term() + transform.translation_term() + fp::subnormal_slack);
  EXPECT_EQ(transform.translation_term(), 0x1p-50 * 10);
}

}  // namespace
}  // namespace cc::bounds
