// The exact reference's measure of the library's rounding (ExactReference::bound_errors) on
// quantities worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "collide/bound_records.h"
#include "oracle/exact/exact_reference.h"

namespace cc::exact {
namespace {

using harness::TermError;

const ExactRationalReference kExact;

std::vector<TermError> of(std::string_view term, const std::vector<TermError>& errors) {
  std::vector<TermError> out;
  for (const TermError& e : errors) {
    if (e.term == term) out.push_back(e);
  }
  return out;
}

TEST(BoundErrors, AQuotientIsMeasuredAgainstItsExactValue) {
  bounds::Records r;
  r.add(bounds::Quotient{1, 0, 3, 0, 0, 1.0 / 3, bounds::kRaySlab});
  r.add(bounds::Quotient{5, 1, 1, 0.5, 2, 32, bounds::kSweepAabbTime});  // (5 - 1) / 0.5 * 4, exact
  const auto errors = kExact.bound_errors(r);
  const auto rounding = of("rounding", errors);
  ASSERT_EQ(rounding.size(), 2u);
  EXPECT_EQ(rounding[0].family, "slab parameter");
  EXPECT_DOUBLE_EQ(rounding[0].error, 0x1p-54 / 3);  // 1/3 = fl(1/3) + 2^-54 / 3
  EXPECT_EQ(rounding[0].bound, 8 * fp::u / 3);
  EXPECT_EQ(rounding[1].family, "aabb time");
  EXPECT_EQ(rounding[1].error, 0);
}

TEST(BoundErrors, AnObbFrameThatIsNotOrthonormalIsMeasuredAgainstTheFrameTerm) {
  // a's first axis is 1 + 2^-49 long (a Gram entry of 2^-48 + 2^-98: at the tolerance); along
  // it, box a reaches (1 + 2^-49)^2 where the formula takes 1.
  const double e = 0x1p-49;
  const Obb a{{0, 0, 0}, {1, 0, 0}, Mat3::from_columns({1 + e, 0, 0}, {0, 1, 0}, {0, 0, 1})};
  const Obb b{{2, 0, 0}, {0, 0, 0}, Mat3::identity()};
  bounds::Records r;
  EXPECT_FALSE(test_obb_obb(a, b, r));  // the first axis separates: 2 (1 + e) - 1 > the bound
  const auto frame = of("frame", kExact.bound_errors(r));
  ASSERT_EQ(frame.size(), 3u);  // a's three face normals, tried at once
  EXPECT_DOUBLE_EQ(frame[0].error, 2 * e + e * e);
  EXPECT_EQ(frame[1].error, 0);  // along a's exact axes y and z, a reaches 0 and b is a point
  EXPECT_EQ(frame[2].error, 0);
  EXPECT_EQ(frame[0].bound, 6 * kObbOrthonormalTolerance);
  EXPECT_FALSE(frame[0].decisive);  // apart by about 1, far beyond its bound
}

TEST(BoundErrors, ASeparatingAxisGapIsMeasuredOnTheSetsAsProjected) {
  const Triangle t{{Vec3{2, 0, 0}, Vec3{3, 0, 0}, Vec3{2, 1, 0}}};
  bounds::SatAxis s{{1, 0, 0}, true, {}, Aabb{{0, 0, 0}, {2, 1, 1}}, t, 0x1p-52, {1, 3, 3, 0}};
  bounds::Records r;
  r.add(s);
  const auto errors = kExact.bound_errors(r);
  const auto projection = of("projection", errors);
  ASSERT_EQ(projection.size(), 1u);
  EXPECT_EQ(projection[0].error, 0x1p-52);  // the exact gap is 0: touching
  EXPECT_TRUE(projection[0].decisive);
  EXPECT_EQ(projection[0].bound, 30 * fp::u);
}

TEST(BoundErrors, AFaceHitIsMeasuredByItsPointsDistanceFromTheTriangle) {
  const Triangle t{{Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 2, 0}}};
  bounds::Records r;
  r.add(bounds::RayMeshFaceHit{{{0.5, 0.5, 4}, {0, 0, -1}}, t, 3.5, {4, 2}});  // stops 0.5 above it
  r.add(bounds::RayMeshFaceHit{{{3, 3, 0}, {1, 0, 0}}, t, -1, {6, 0x1p10}});  // (2, 3, 0): sqrt(4.5) off
  const auto errors = kExact.bound_errors(r);
  ASSERT_EQ(of("origin", errors).size(), 1u);
  EXPECT_DOUBLE_EQ(of("origin", errors)[0].error, 0.5);
  EXPECT_EQ(of("origin", errors)[0].bound, 0x1p-40 * 2);  // half the origin's part of the pad
  ASSERT_EQ(of("mesh", errors).size(), 1u);
  EXPECT_DOUBLE_EQ(of("mesh", errors)[0].error, std::sqrt(4.5));
}

TEST(BoundErrors, PlacementsAreAtTheirDecisionOnlyAtTheFittedBoxsExtremes) {
  const Mesh mesh{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 0}}, {{0, 1, 2}}};
  const RigidTransform pose{Mat3::from_columns({0.6, 0.8, 0}, {-0.8, 0.6, 0}, {0, 0, 1}), {0x1p40, 3, 0}};
  bounds::Records r;
  fitted_box(mesh, pose, r);
  const auto translation = of("translation", kExact.bound_errors(r));
  ASSERT_EQ(translation.size(), 7u);  // the translation's term is the larger
  EXPECT_TRUE(translation[0].decisive);
  EXPECT_FALSE(translation[6].decisive);  // the origin: inside the others on every axis
  for (const TermError& e : translation) EXPECT_LE(e.error, e.bound);
}

TEST(BoundErrors, ACubeMeasuresHowFarARotationStretchesAVertex) {
  // Rows 1 + 2^-50 long: the vertex (1, 0, 0) reaches 1 + 2^-50 on x.
  const Mesh mesh{{{1, 0, 0}}, {}};
  const RigidTransform pose{Mat3::from_columns({1 + 0x1p-50, 0, 0}, {0, 1, 0}, {0, 0, 1}), {0, 0, 0}};
  bounds::Records r;
  bounding_cube(rotation_radius(mesh, r), pose, r);
  const auto orthonormality = of("orthonormality", kExact.bound_errors(r));
  ASSERT_EQ(orthonormality.size(), 1u);
  EXPECT_DOUBLE_EQ(orthonormality[0].error, 0x1p-50);
}

}  // namespace
}  // namespace cc::exact
