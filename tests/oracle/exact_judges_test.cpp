// The exact reference's verdicts on cases worked out by hand.
#include "oracle/exact/judges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc::exact {
namespace {

using harness::Contract;
const double kNan = std::numeric_limits<double>::quiet_NaN();
const Aabb kUnit{{0, 0, 0}, {1, 1, 1}};

harness::RayAabbInput ray(Vec3 o, Vec3 d, double tmin = 0, double tmax = INFINITY) { return {{o, d, tmin, tmax}, kUnit}; }

TEST(JudgeRayAabb, HitThroughTheMiddle) {
  // Along x through the centre: t in [1, 2]; the box may shrink by 0.5 before the ray misses.
  const ExactVerdict v = judge(ray({-1, 0.5, 0.5}, {1, 0, 0}));
  EXPECT_EQ(v.contract, Contract::in);
  EXPECT_TRUE(v.answer.hit);
  EXPECT_EQ(v.answer.params, (std::vector<double>{1, 2}));
  EXPECT_DOUBLE_EQ(v.margin, 0.5);
}

TEST(JudgeRayAabb, MissAndTouch) {
  // Parallel to y's slab, 1 above it: the box must grow by 1; scale 2.
  const ExactVerdict miss = judge(ray({-1, 2, 0.5}, {1, 0, 0}));
  EXPECT_FALSE(miss.answer.hit);
  EXPECT_DOUBLE_EQ(miss.margin, -0.5);
  // On the boundary of that slab: touching, margin 0.
  const ExactVerdict touch = judge(ray({-1, 1, 0.5}, {1, 0, 0}));
  EXPECT_TRUE(touch.answer.hit);
  EXPECT_EQ(touch.margin, 0);
  // Diagonal past a corner: entry on x at t = 2 after exit on y at t = 1.5: the box must grow
  // by (2 - 1.5) * 1 * 1 / (1 + 1) = 0.25; scale 2.
  const ExactVerdict corner = judge(ray({-2, -0.5, 0.5}, {1, 1, 0}));
  EXPECT_FALSE(corner.answer.hit);
  EXPECT_DOUBLE_EQ(corner.margin, -0.125);
}

TEST(JudgeRayAabb, ContractAndDocumentedAnswers) {
  EXPECT_EQ(judge(ray({kNan, 0.5, 0.5}, {1, 0, 0})).contract, Contract::documented);
  EXPECT_FALSE(judge(ray({kNan, 0.5, 0.5}, {1, 0, 0})).answer.hit);
  EXPECT_EQ(judge(ray({-INFINITY, 0.5, 0.5}, {1, 0, 0})).contract, Contract::documented);
  // A component whose reciprocal overflows is parallel by contract: in the domain, with a note.
  const ExactVerdict tiny = judge(ray({0.5, -1, 0.5}, {std::numeric_limits<double>::denorm_min(), 1, 0}));
  EXPECT_EQ(tiny.contract, Contract::in);
  EXPECT_TRUE(tiny.answer.hit);
  EXPECT_FALSE(tiny.note.empty());
  // A slab parameter beyond 2^1000: outside the domain, unspecified.
  EXPECT_EQ(judge(ray({-1, 0.5, 0.5}, {0x1p-1000, 1, 0})).contract, Contract::unspecified);
}

TEST(JudgeSphereSphere, MarginIsTheGapBetweenSurfacesOverTheScale) {
  EXPECT_EQ(judge(harness::SphereSphereInput{{{0, 0, 0}, 2}, {{3, 4, 0}, 3}}).margin, 0);
  const ExactVerdict apart = judge(harness::SphereSphereInput{{{0, 0, 0}, 1}, {{4, 0, 0}, 1}});
  EXPECT_FALSE(apart.answer.hit);
  EXPECT_DOUBLE_EQ(apart.margin, -0.5);
  EXPECT_EQ(judge(harness::SphereSphereInput{{{0, 0, 0}, -1}, {{0, 0, 0}, 1}}).contract, Contract::documented);
  EXPECT_EQ(judge(harness::SphereSphereInput{{{0x1p501, 0, 0}, 1}, {{0, 0, 0}, 1}}).contract, Contract::unspecified);
}

// Rationals have no range limit: finite inputs beyond the library's range are decided all the
// same (out of its contract, so the library is not judged, but a second opinion is), with the
// margin of the same shapes at scale 1.
TEST(JudgeSphereSphere, DecidesSubnormalAndHugeInputs) {
  for (const double s : {0x1p-1072, 0x1p-1060, 0x1p-600, 0x1p600, 0x1p1000}) {
    const ExactVerdict touching = judge(harness::SphereSphereInput{{{0, 0, 0}, 2 * s}, {{4 * s, 0, 0}, 2 * s}});
    EXPECT_EQ(touching.contract, Contract::unspecified) << s;
    EXPECT_TRUE(touching.decided) << s;
    EXPECT_TRUE(touching.answer.hit) << s;
    EXPECT_EQ(touching.margin, 0) << s;
    EXPECT_FALSE(touching.note.empty());
    const ExactVerdict apart = judge(harness::SphereSphereInput{{{0, 0, 0}, s}, {{4 * s, 0, 0}, s}});
    EXPECT_TRUE(apart.decided) << s;
    EXPECT_FALSE(apart.answer.hit) << s;
    EXPECT_DOUBLE_EQ(apart.margin, -0.5) << s;
    const ExactVerdict overlapping = judge(harness::SphereSphereInput{{{0, 0, 0}, 2 * s}, {{3 * s, 0, 0}, 2 * s}});
    EXPECT_TRUE(overlapping.answer.hit) << s;
    EXPECT_GT(overlapping.margin, 0) << s;
  }
  // One ulp apart at the bottom of the subnormals: still exact.
  const ExactVerdict ulp = judge(harness::SphereSphereInput{{{0, 0, 0}, 0x1p-1074}, {{0x1p-1072, 0, 0}, 0x1p-1074}});
  EXPECT_TRUE(ulp.decided);
  EXPECT_FALSE(ulp.answer.hit);
  EXPECT_LT(ulp.margin, 0);
}

TEST(JudgeTriTri, DecidesSubnormalAndHugeInputs) {
  for (const double s : {0x1p-1070, 0x1p-400, 0x1p400, 0x1p1000}) {
    const auto v = [s](double x, double y, double z) { return Vec3{x * s, y * s, z * s}; };
    const Triangle a{{v(0, 0, 0), v(4, 0, 0), v(0, 4, 0)}};
    const ExactVerdict crossing = judge(harness::TriTriInput{a, {{v(1, 1, -1), v(1, 1, 1), v(2, 2, 1)}}});
    EXPECT_EQ(crossing.contract, Contract::unspecified) << s;
    EXPECT_TRUE(crossing.decided) << s;
    EXPECT_TRUE(crossing.answer.hit) << s;
    const ExactVerdict touching = judge(harness::TriTriInput{a, {{v(1, 1, 0), v(1, 1, 1), v(2, 2, 1)}}});
    EXPECT_TRUE(touching.answer.hit) << s;
    EXPECT_EQ(touching.margin, 0) << s;
    const ExactVerdict apart = judge(harness::TriTriInput{a, {{v(1, 1, 1), v(1, 1, 2), v(2, 2, 2)}}});
    EXPECT_TRUE(apart.decided) << s;
    EXPECT_FALSE(apart.answer.hit) << s;
    EXPECT_LT(apart.margin, 0) << s;
  }
}

TEST(JudgeObbObb, DecidesSubnormalAndHugeInputs) {
  const Mat3 identity = Mat3::from_columns({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  for (const double s : {0x1p-1070, 0x1p-600, 0x1p600, 0x1p1000}) {
    const Obb a{{0, 0, 0}, {s, s, s}, identity};
    const ExactVerdict touching = judge(harness::ObbObbInput{a, {{2 * s, 0, 0}, {s, s, s}, identity}});
    EXPECT_EQ(touching.contract, Contract::unspecified) << s;
    EXPECT_TRUE(touching.decided) << s;
    EXPECT_TRUE(touching.answer.hit) << s;
    EXPECT_EQ(touching.margin, 0) << s;
    const ExactVerdict apart = judge(harness::ObbObbInput{a, {{3 * s, 0, 0}, {s, s, s}, identity}});
    EXPECT_FALSE(apart.answer.hit) << s;
    EXPECT_LT(apart.margin, 0) << s;
    const auto t = [](Vec3 p, Vec3 q, Vec3 r) { return Triangle{{p, q, r}}; };
    const harness::TriObbInput tri{t({0, 0, s}, {s, 0, s}, {0, s, s}), a};
    EXPECT_TRUE(judge(tri).answer.hit) << s;
    EXPECT_TRUE(judge(tri).decided) << s;
    const harness::TriAabbInput tri_box{t({0, 0, s}, {s, 0, s}, {0, s, 2 * s}), {{-s, -s, -s}, {s, s, s}}};
    EXPECT_TRUE(judge(tri_box).answer.hit) << s;
    const harness::TriAabbInput tri_apart{t({0, 0, 2 * s}, {s, 0, 2 * s}, {0, s, 2 * s}), {{-s, -s, -s}, {s, s, s}}};
    EXPECT_FALSE(judge(tri_apart).answer.hit) << s;
    EXPECT_EQ(judge(tri_apart).contract, Contract::unspecified) << s;
  }
}

TEST(JudgeAabbAabb, MarginIsTheSmallestOverlap) {
  EXPECT_DOUBLE_EQ(judge(harness::AabbAabbInput{kUnit, {{0.75, 0, 0}, {1.75, 1, 1}}}).margin, 0.25 / 1.75);
  const ExactVerdict apart = judge(harness::AabbAabbInput{kUnit, {{3, 0, 0}, {4, 1, 1}}});
  EXPECT_FALSE(apart.answer.hit);
  EXPECT_DOUBLE_EQ(apart.margin, -2.0 / 4);
  EXPECT_EQ(judge(harness::AabbAabbInput{kUnit, {{1, 0, 0}, {0, 1, 1}}}).contract, Contract::documented);
}

TEST(JudgeKdopKdop, SeparatedOnADiagonalSlab) {
  // {(0,1),(1,0)} and {(1,2),(2,1)} on (1,1,0): [1,1] and [3,3], a gap of 2 / sqrt(2); scale 2.
  const ExactVerdict v = judge(harness::KdopKdopInput{18, {{0, 1, 0}, {1, 0, 0}}, {{1, 2, 0}, {2, 1, 0}}});
  EXPECT_FALSE(v.answer.hit);
  EXPECT_NEAR(v.margin, -std::sqrt(2.0) / 2, 1e-15);
  EXPECT_TRUE(judge(harness::KdopKdopInput{6, {{0, 1, 0}, {1, 0, 0}}, {{1, 2, 0}, {2, 1, 0}}}).answer.hit);
}

TEST(JudgeObbObb, TheBoxIsTheParallelepipedOfItsMatrix) {
  const Obb a{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  EXPECT_TRUE(judge(harness::ObbObbInput{a, {{2, 0, 0}, {1, 1, 1}, Mat3::identity()}}).answer.hit);
  EXPECT_EQ(judge(harness::ObbObbInput{a, {{2, 0, 0}, {1, 1, 1}, Mat3::identity()}}).margin, 0);
  // A matrix beyond the orthonormality tolerance is outside the domain.
  const Mat3 stretched = Mat3::from_columns({1 + 0x1p-40, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_EQ(judge(harness::ObbObbInput{a, {{5, 0, 0}, {1, 1, 1}, stretched}}).contract, Contract::unspecified);
  EXPECT_EQ(judge(harness::ObbObbInput{a, {{5, 0, 0}, {-1, 1, 1}, Mat3::identity()}}).contract, Contract::documented);
}

TEST(JudgeTriangles, DomainsAndAnswers) {
  const Triangle t{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}};
  EXPECT_TRUE(judge(harness::TriTriInput{t, t}).answer.hit);
  EXPECT_EQ(judge(harness::TriTriInput{t, {{Vec3{0, 0, kNan}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}}}).contract,
            Contract::documented);
  EXPECT_EQ(judge(harness::TriTriInput{t, {{Vec3{0, 0, 0x1p301}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}}}).contract,
            Contract::unspecified);
  EXPECT_TRUE(judge(harness::TriAabbInput{t, {{0, 0, 0}, {0, 0, 0}}}).answer.hit);  // a point box at a vertex
  EXPECT_FALSE(judge(harness::TriAabbInput{t, {{0.6, 0.6, 0}, {0.6, 0.6, 0}}}).answer.hit);
}

TEST(JudgeTriTriIntersection, TheCornersAndTheirTolerance) {
  const Triangle up{{Vec3{0, 0, 0}, Vec3{6, 0, 0}, Vec3{3, 6, 0}}}, down{{Vec3{0, 4, 0}, Vec3{3, -2, 0}, Vec3{6, 4, 0}}};
  const ExactVerdict star = judge(harness::TriTriIntersectionInput{up, down});
  EXPECT_TRUE(star.answer.hit);
  EXPECT_EQ(star.answer.params.size(), 18u);  // the hexagon's six corners
  EXPECT_EQ(star.margin, judge(harness::TriTriInput{up, down}).margin);
  // Touching at a vertex: that vertex, condition 1; apart: no corners.
  const ExactVerdict vertex = judge(harness::TriTriIntersectionInput{up, {{Vec3{0, 0, 0}, Vec3{-1, 0, 1}, Vec3{0, -1, 1}}}});
  EXPECT_EQ(vertex.answer.params, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(vertex.corner_tolerance, 0x1p-44 * 6 + 0x1p-48 * 6 + 0x1p-1074);
  const ExactVerdict apart = judge(harness::TriTriIntersectionInput{up, {{Vec3{0, 0, 1}, Vec3{1, 0, 1}, Vec3{0, 1, 1}}}});
  EXPECT_FALSE(apart.answer.hit);
  EXPECT_TRUE(apart.answer.params.empty());
  // Out of the domain as tri_tri: NaN is a documented miss, beyond 2^300 decided but unspecified.
  EXPECT_EQ(judge(harness::TriTriIntersectionInput{up, {{Vec3{0, 0, kNan}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}}}).contract,
            Contract::documented);
  const ExactVerdict huge = judge(harness::TriTriIntersectionInput{up, {{Vec3{0, 0, 0x1p301}, Vec3{1, 0, 0}, Vec3{0, 0, -1}}}});
  EXPECT_EQ(huge.contract, Contract::unspecified);
  EXPECT_TRUE(huge.decided);
  EXPECT_EQ(huge.answer.params.size(), 6u);
}

harness::DiscWallsInput disc_walls(Disc disc, std::vector<Wall> walls) { return {disc, std::move(walls)}; }
const Wall kFloor{{0, 0}, {2, 0}};  // scale 2 with a disc near it

// Every wall on its own: touched at its side, at an end (3-4-5), as a pillar; the margin is the
// gap over that wall's scale, the case's the wall's nearest 0.
TEST(JudgeDiscWalls, EachWallTouchedOrApartAtItsOwnMargin) {
  const ExactVerdict side = judge(disc_walls({{1, 0.5}, 0.5}, {kFloor}));
  EXPECT_EQ(side.contract, Contract::in);
  EXPECT_EQ(side.answer.pairs, (std::vector<harness::FacePair>{{0, 0}}));
  EXPECT_TRUE(side.answer.hit);
  EXPECT_EQ(side.margin, 0);
  const ExactVerdict end = judge(disc_walls({{-3, 4}, 5}, {{{0, 0}, {8, 0}}}));  // nearest point: the end a
  EXPECT_TRUE(end.answer.hit);
  EXPECT_EQ(end.margin, 0);
  EXPECT_EQ(judge(disc_walls({{0, 0}, 5}, {{{3, 4}, {3, 4}}})).margin, 0);  // a pillar
  // 1.5 apart over the scale 2; the far wall (scale 2^20) is apart by more.
  const ExactVerdict apart = judge(disc_walls({{1, 2}, 0.5}, {kFloor, {{0x1p20, 0}, {0x1p20, 1}}}));
  EXPECT_FALSE(apart.answer.hit);
  EXPECT_TRUE(apart.answer.pairs.empty());
  EXPECT_DOUBLE_EQ(apart.margin, -0.75);
  EXPECT_DOUBLE_EQ(apart.margin_of({0, 0}), -0.75);
  EXPECT_NEAR(apart.margin_of({1, 0}), -(0x1p20 - 1.5) / 0x1p20, 1e-9);
  // Overlapping by 0.25 (scale 2), and the other wall touching: the case's margin is 0.
  const ExactVerdict two = judge(disc_walls({{1, 0.25}, 0.5}, {kFloor, {{0, 0.75}, {2, 0.75}}}));
  EXPECT_EQ(two.answer.pairs, (std::vector<harness::FacePair>{{0, 0}, {1, 0}}));
  EXPECT_DOUBLE_EQ(two.margin_of({0, 0}), 0.125);
  EXPECT_EQ(two.margin, 0);
}

// One ulp apart or overlapping, and by a subnormal: never margin 0.
TEST(JudgeDiscWalls, AMarginIsZeroOnlyForATouch) {
  const ExactVerdict ulp = judge(disc_walls({{1, std::nextafter(0.5, 1.0)}, 0.5}, {kFloor}));
  EXPECT_FALSE(ulp.answer.hit);
  EXPECT_LT(ulp.margin, 0);
  EXPECT_GT(ulp.margin, -0x1p-50);
  const double tiny = std::numeric_limits<double>::denorm_min();
  const ExactVerdict apart = judge(disc_walls({{0, 2 * tiny}, tiny}, {{{-1, 0}, {1, 0}}}));
  EXPECT_FALSE(apart.answer.hit);
  EXPECT_LT(apart.margin, 0);
  const ExactVerdict overlapping = judge(disc_walls({{0, tiny}, 2 * tiny}, {{{-1, 0}, {1, 0}}}));
  EXPECT_TRUE(overlapping.answer.hit);
  EXPECT_GT(overlapping.margin, 0);
  // A tiny scale: every value below 2^-1000, the margin still the gap over the scale.
  const ExactVerdict small = judge(disc_walls({{0x1p-1010, 0x1p-1010}, 0}, {{{0, 0}, {0x1p-1009, 0}}}));
  EXPECT_FALSE(small.answer.hit);
  EXPECT_DOUBLE_EQ(small.margin, -0.5);
}

// A disc out of the domain has the documented answer; a wall with a NaN or infinite end is never
// touched (margin -inf) while the others are judged; beyond 2^500 the verdict stands, unspecified.
TEST(JudgeDiscWalls, ContractAndDocumentedAnswers) {
  for (const Disc& d : {Disc{{kNan, 0}, 1}, Disc{{0, INFINITY}, 1}, Disc{{0, 0}, kNan}, Disc{{0, 0}, -1}}) {
    const ExactVerdict v = judge(disc_walls(d, {kFloor}));
    EXPECT_EQ(v.contract, Contract::documented);
    EXPECT_FALSE(v.answer.hit);
  }
  const ExactVerdict nan_wall = judge(disc_walls({{1, 0}, 0}, {{{kNan, 0}, {2, 0}}, kFloor}));
  EXPECT_EQ(nan_wall.contract, Contract::in);
  EXPECT_EQ(nan_wall.answer.pairs, (std::vector<harness::FacePair>{{1, 0}}));
  EXPECT_EQ(nan_wall.margin_of({0, 0}), -INFINITY);
  EXPECT_EQ(nan_wall.margin, 0);
  const ExactVerdict huge = judge(disc_walls({{0, 0}, 0x1p501}, {kFloor}));
  EXPECT_EQ(huge.contract, Contract::unspecified);
  EXPECT_TRUE(huge.decided);
  EXPECT_TRUE(huge.answer.hit);
  const ExactVerdict none = judge(disc_walls({{0, 0}, 1}, {}));
  EXPECT_EQ(none.contract, Contract::in);
  EXPECT_FALSE(none.answer.hit);
  EXPECT_EQ(none.margin, -INFINITY);
}

}  // namespace
}  // namespace cc::exact
