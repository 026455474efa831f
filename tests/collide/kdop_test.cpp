#include "collide/kdop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "collide/simd.h"

namespace cc {
namespace {

TEST(KdopDirections, HaveKOverTwoSlabsInFclsOrder) {
  EXPECT_EQ(kdop_directions<6>().size(), 3u);
  EXPECT_EQ(kdop_directions<14>().size(), 7u);
  EXPECT_EQ(kdop_directions<16>().size(), 8u);
  EXPECT_EQ(kdop_directions<18>().size(), 9u);
  EXPECT_EQ(kdop_directions<24>().size(), 12u);
  EXPECT_EQ(kdop_directions<26>().size(), 13u);
  // FCL's N=24: the 18 ones, then (1,1,-1) (1,-1,1) (-1,1,1).
  const auto d = kdop_directions<24>();
  EXPECT_EQ(d[8].y, 1);
  EXPECT_EQ(d[8].z, -1);
  EXPECT_EQ(d[11].x, -1);
  EXPECT_TRUE(kdop_directions(12).empty());
}

// Each set is the one its comment documents, as a set of lines (a direction and its negation are
// one slab), with no line twice: the exact reference reads the same tables, so only this test
// notices a wrong direction in them.
TEST(KdopDirections, AreTheDocumentedLinesEachOnce) {
  using Line = std::array<int, 3>;
  const auto lines = [](int k) {
    std::vector<Line> out;
    for (const KdopDirection& d : kdop_directions(k)) {
      Line l{static_cast<int>(d.x), static_cast<int>(d.y), static_cast<int>(d.z)};
      const int first = l[0] != 0 ? l[0] : (l[1] != 0 ? l[1] : l[2]);
      if (first < 0) l = {-l[0], -l[1], -l[2]};
      out.push_back(l);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const std::vector<Line> axes = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  const std::vector<Line> corners = {{1, -1, -1}, {1, -1, 1}, {1, 1, -1}, {1, 1, 1}};
  const std::vector<Line> edges = {{0, 1, -1}, {0, 1, 1}, {1, -1, 0}, {1, 0, -1}, {1, 0, 1}, {1, 1, 0}};
  const auto joined = [](std::vector<std::vector<Line>> parts) {
    std::vector<Line> out;
    for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(lines(6), axes);
  EXPECT_EQ(lines(14), joined({axes, corners}));
  EXPECT_EQ(lines(18), joined({axes, edges}));
  EXPECT_EQ(lines(26), joined({axes, corners, edges}));
  for (int k : {16, 24}) {
    const std::vector<Line> l = lines(k);
    EXPECT_EQ(std::adjacent_find(l.begin(), l.end()), l.end()) << k << ": a line twice";
  }
}

TEST(FitKdop, SixDopIsTheBoundingBoxExactly) {
  const std::vector<Vec3> points = {{0.1, 0.2, 0.3}, {-1, 5, 0.3}, {2, -0.5, 7}};
  const Kdop<6> dop = fit_kdop<6>(points);
  EXPECT_EQ(dop.lo[0], -1);
  EXPECT_EQ(dop.hi[0], 2);
  EXPECT_EQ(dop.lo[1], -0.5);
  EXPECT_EQ(dop.hi[2], 7);
}

TEST(FitKdop, RoundsSumsOutward) {
  // 0.1 + 0.2 rounds up to 0.30000000000000004, which is above the exact sum; the fitted slab
  // must still contain the exact sum on both sides.
  const std::vector<Vec3> points = {{0.1, 0.2, 0}};
  const Kdop<18> dop = fit_kdop<18>(points);
  EXPECT_LE(dop.lo[3], 0.3);  // (1,1,0): 0.1 + 0.2 = 0.3000000000000000166... exactly
  EXPECT_GE(dop.hi[3], 0.30000000000000004);
}

TEST(TestKdopKdop, TouchingOnASlabOverlaps) {
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 0, 0}};
  const std::vector<Vec3> b = {{1, 0, 0}, {2, 0, 0}};
  EXPECT_TRUE(test_kdop_kdop(fit_kdop<14>(a), fit_kdop<14>(b)));
  const std::vector<Vec3> apart = {{1.5, 0, 0}, {2, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<14>(a), fit_kdop<14>(apart)));
}

TEST(TestKdopKdop, DiagonalSlabsSeparateWhatTheBoxesDoNot) {
  // The boxes [0,1]^2 and [1,2]x[1,2] touch at a corner; on the (1,1,0) slab the point sets
  // {(0,1),(1,0)} and {(1,2),(2,1)} project to [1,1] and [3,3]: the 18-DOP separates them.
  const std::vector<Vec3> a = {{0, 1, 0}, {1, 0, 0}};
  const std::vector<Vec3> b = {{1, 2, 0}, {2, 1, 0}};
  const std::vector<Vec3> corner_box = {{1, 1, 0}, {2, 2, 0}};
  EXPECT_TRUE(test_kdop_kdop(fit_kdop<6>(a), fit_kdop<6>(corner_box)));
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<18>(a), fit_kdop<18>(b)));
}

TEST(TestKdopKdop, EmptyAndNonFiniteKdopsOverlapNothing) {
  const std::vector<Vec3> a = {{0, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<18>(a), Kdop<18>{}));
  const std::vector<Vec3> nan = {{std::numeric_limits<double>::quiet_NaN(), 0, 0}, {0, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<18>(a), fit_kdop<18>(nan)));
  const std::vector<Vec3> inf = {{INFINITY, 0, 0}, {0, 0, 0}};
  EXPECT_FALSE(test_kdop_kdop(fit_kdop<26>(a), fit_kdop<26>(inf)));
}

TEST(TestKdopKdop, IsSymmetric) {
  const std::vector<Vec3> a = {{0.1, 0.2, 0.3}, {0.5, -0.25, 1}};
  const std::vector<Vec3> b = {{0.4, 0.2, 0.9}};
  EXPECT_EQ(test_kdop_kdop(fit_kdop<24>(a), fit_kdop<24>(b)), test_kdop_kdop(fit_kdop<24>(b), fit_kdop<24>(a)));
}

// The definition of fit_kdop without its specialisations: every slab from sum3 of the three
// exact products, widened by 4u of sum3 of their magnitudes for 2- and 3-term directions.
template <int K>
Kdop<K> plain_fit(const std::vector<Vec3>& points) {
  Kdop<K> dop;
  const auto dirs = kdop_directions<K>();
  for (const Vec3& p : points) {
    for (int i = 0; i < K / 2; ++i) {
      const double tx = dirs[i].x * p.x, ty = dirs[i].y * p.y, tz = dirs[i].z * p.z;
      const int terms = (dirs[i].x != 0) + (dirs[i].y != 0) + (dirs[i].z != 0);
      const double s = fp::sum3(tx, ty, tz);
      const double pad = (terms > 1 ? 4 * fp::u : 0.0) * fp::sum3(std::fabs(tx), std::fabs(ty), std::fabs(tz));
      dop.lo[i] = std::min(dop.lo[i], s - pad);
      dop.hi[i] = std::max(dop.hi[i], s + pad);
    }
  }
  return dop;
}

template <int K>
void expect_same_bits(const std::vector<Vec3>& points) {
  const Kdop<K> fast = fit_kdop<K>(points), plain = plain_fit<K>(points);
  for (int i = 0; i < K / 2; ++i) {
    EXPECT_EQ(std::signbit(fast.lo[i]), std::signbit(plain.lo[i])) << "k " << K << " slab " << i;
    EXPECT_EQ(std::signbit(fast.hi[i]), std::signbit(plain.hi[i])) << "k " << K << " slab " << i;
    EXPECT_EQ(fast.lo[i], plain.lo[i]) << "k " << K << " slab " << i;
    EXPECT_EQ(fast.hi[i], plain.hi[i]) << "k " << K << " slab " << i;
  }
}

// fit_kdop with every kernel this processor runs (the points taken 1, 4 or 8 at a time, the
// lanes merged at the end, a zero bound taken from the plain loop), against the definition.
TEST(FitKdop, IsItsPlainDefinitionBitForBitSignedZerosIncludedWithEveryKernel) {
  // Coordinates that make sums cancel to +0 or -0, and ordinary ones; sets of 1 to 19 points,
  // so that every kernel has blocks and a last block that repeats the last point.
  const double values[] = {0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 0.3, 1e-300, -1e-300, 0x1p-1074, 3.5, 0x1p1000, -0x1p1023};
  for (simd::Kernel kernel : simd::supported_kernels()) {
    const simd::ForcedKernel forced(kernel);
    unsigned state = 12345;
    const auto next = [&] { return state = state * 1103515245u + 12345u, values[(state >> 16) % std::size(values)]; };
    for (int round = 0; round < 400; ++round) {
      std::vector<Vec3> points;
      for (int j = 0; j < 1 + round % 19; ++j) points.push_back({next(), next(), next()});
      SCOPED_TRACE(std::string(simd::to_string(kernel)) + ", round " + std::to_string(round));
      expect_same_bits<6>(points);
      expect_same_bits<14>(points);
      expect_same_bits<16>(points);
      expect_same_bits<18>(points);
      expect_same_bits<24>(points);
      expect_same_bits<26>(points);
    }
  }
}

}  // namespace
}  // namespace cc
