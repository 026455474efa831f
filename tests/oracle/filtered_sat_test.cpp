// sat_verdict: exact_sat's answer bit for bit on boxes and triangles that touch, lie apart,
// overlap, have parallel edges, are flat or degenerate, and sit at extreme scales; and which
// path decided each: the filter with few axes taken exactly, or exact_sat whole.
#include "oracle/exact/filtered_sat.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include "rotations.h"

namespace cc::exact {
namespace {

enum class Path { filtered, whole };

struct Outcome {
  TriangleSatVerdict verdict;
  Path path;
  long exact_axes;
};

// sat_verdict(a, b), checked against exact_sat, with the path it took.
Outcome checked(const SatInput& a, const SatInput& b) {
  const SatFilterCounts before = sat_filter_counts();
  const TriangleSatVerdict got = sat_verdict(a, b);
  const SatFilterCounts after = sat_filter_counts();
  const SatResult expected = exact_sat(exact_shape(a, "A"), exact_shape(b, "B"));
  EXPECT_EQ(got.hit, expected.hit);
  EXPECT_EQ(got.rank, expected.rank);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.margin), std::bit_cast<std::uint64_t>(expected.margin))
      << got.margin << " against " << expected.margin;
  return {got, after.filtered > before.filtered ? Path::filtered : Path::whole, after.exact_axes - before.exact_axes};
}

const Aabb kUnitBox{{0, 0, 0}, {1, 1, 1}};

TEST(SatVerdict, ATriangleTouchingABoxFaceIsAHitOfMarginZeroInFloatingPointAlone) {
  // A vertex on the face x = 1 and the triangle's plane parallel to it: the gap along x is
  // exactly 0 in floating point.
  const Outcome o = checked(kUnitBox, Triangle{{{{1, 0.5, 0.5}, {2, 0.5, 0.5}, {2, 0.75, 0.5}}}});
  EXPECT_TRUE(o.verdict.hit);
  EXPECT_EQ(o.verdict.margin, 0);
  EXPECT_EQ(o.path, Path::filtered);
  EXPECT_EQ(o.exact_axes, 0);
}

TEST(SatVerdict, ATriangleApartFromABoxTakesTheDecidingAxisExactly) {
  const Outcome o = checked(kUnitBox, Triangle{{{{1.1, 0.3, 0.3}, {2, 0.1, 0.7}, {1.7, 0.9, 0.2}}}});
  EXPECT_FALSE(o.verdict.hit);
  EXPECT_LT(o.verdict.margin, 0);
  EXPECT_EQ(o.path, Path::filtered);
  EXPECT_GE(o.exact_axes, 1);
  EXPECT_LE(o.exact_axes, 3);
}

TEST(SatVerdict, RotatedBoxesThatOverlapGiveTheSmallestOverlap) {
  const Obb a{{0, 0, 0}, {1, 2, 3}, test::rotation(0.3, 0.2, 0.1)};
  const Obb b{{1.5, 0.5, -0.5}, {1, 1, 0.5}, test::rotation(-0.4, 0.9, 0.3)};
  const Outcome o = checked(a, b);
  EXPECT_TRUE(o.verdict.hit);
  EXPECT_GT(o.verdict.margin, 0);
  EXPECT_EQ(o.path, Path::filtered);
}

TEST(SatVerdict, ABoxFaceAndAParallelTriangleAHairApartAreSeparated) {
  // One ulp of 1 beyond the face x = 1.
  const double x = std::nextafter(1.0, 2.0);
  const Outcome o = checked(kUnitBox, Triangle{{{{x, 0.25, 0.25}, {x, 0.75, 0.25}, {x, 0.25, 0.75}}}});
  EXPECT_FALSE(o.verdict.hit);
  EXPECT_EQ(o.path, Path::filtered);
}

TEST(SatVerdict, FlatAndLowerRankPairsGoToExactSatWhole) {
  // A flat box and a triangle in its plane (rank 2), a segment and a point box (rank 1).
  const Aabb flat{{0, 0, 0}, {1, 1, 0}};
  EXPECT_EQ(checked(flat, Triangle{{{{0.5, 0.5, 0}, {2, 0.5, 0}, {0.5, 2, 0}}}}).path, Path::whole);
  const Aabb segment{{0, 0, 0}, {1, 0, 0}};
  EXPECT_EQ(checked(segment, Triangle{{{{2, 0, 0}, {3, 0, 0}, {3, 0, 0}}}}).path, Path::whole);
}

TEST(SatVerdict, ExtremeScalesGoToExactSatWhole) {
  // Products of coordinates near 2^1000 overflow; squares near 2^-1000 underflow.
  const double big = 0x1p1000, small = 0x1p-1000;
  EXPECT_EQ(checked(Aabb{{0, 0, 0}, {big, big, big}}, Triangle{{{{big, 0, 0}, {2 * big, big, 0}, {big, 0, big}}}}).path,
            Path::whole);
  EXPECT_EQ(checked(Aabb{{0, 0, 0}, {small, small, small}}, Triangle{{{{small, 0, 0}, {2 * small, small, 0}, {small, 0, small}}}}).path,
            Path::whole);
  // Inside the range both ways, the filter decides.
  const double s = 0x1p-300, l = 0x1p300;
  EXPECT_EQ(checked(Aabb{{0, 0, 0}, {s, s, s}}, Triangle{{{{s, 0, 0}, {2 * s, s, 0}, {s, 0, s}}}}).path, Path::filtered);
  EXPECT_EQ(checked(Aabb{{0, 0, 0}, {l, l, l}}, Triangle{{{{l, 0, 0}, {2 * l, l, 0}, {l, 0, l}}}}).path, Path::filtered);
}

TEST(SatVerdict, EdgesParallelToTheBoxAxesAreDroppedInFloatingPoint) {
  // Every triangle edge along a box axis: the cross products that vanish are exact zeros.
  const Outcome o = checked(kUnitBox, Triangle{{{{2, 0, 0}, {3, 0, 0}, {2, 1, 0}}}});
  EXPECT_FALSE(o.verdict.hit);
  EXPECT_EQ(o.path, Path::filtered);
  EXPECT_LE(o.exact_axes, 2);  // only axes that may give the margin (x and one tied with it)
}

}  // namespace
}  // namespace cc::exact
