#include "collide/ray_aabb_batch.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace cc {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
const double kDenormMin = std::numeric_limits<double>::denorm_min();

// Every box of the batch, as the selected kernel answers, against the scalar test box by box
// and against the scalar kernel; the bits past the last box must be cleared (the words are
// filled with ones and with a pattern before). Returns the number of hits.
std::size_t expect_same_as_scalar(const Ray& ray, const AabbSoa& boxes) {
  std::vector<std::uint64_t> hits(hit_words(boxes.size()), ~std::uint64_t{0});
  std::vector<std::uint64_t> scalar_hits(hit_words(boxes.size()), 0x5555555555555555);
  const std::size_t count = test_ray_aabbs(ray, boxes, hits);
  const simd::Kernel kernel = simd::selected();
  const std::size_t scalar_count = test_ray_aabbs(ray, boxes, scalar_hits, simd::Kernel::scalar);
  std::size_t expected = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const bool scalar = intersect_ray_aabb(ray, boxes[i]).hit;
    expected += scalar;
    EXPECT_EQ(hit_bit(hits, i), scalar) << to_string(kernel) << ", box " << i << " of " << boxes.size();
  }
  EXPECT_EQ(hits, scalar_hits) << to_string(kernel) << " against the scalar kernel, " << boxes.size() << " boxes";
  if (boxes.size() % 64 != 0) {
    EXPECT_EQ(hits.back() >> (boxes.size() % 64), 0u) << to_string(kernel) << ": bits past the last box";
  }
  EXPECT_EQ(count, expected);
  EXPECT_EQ(count, scalar_count);
  return count;
}

// The hit bits as a string, box 0 first.
std::string bits_of(const std::vector<std::uint64_t>& hits, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) out += hit_bit(hits, i) ? '1' : '0';
  return out;
}

// Each test runs once per kernel, forced; a kernel this processor lacks is skipped with the
// reason (simd::unsupported_reason), so a machine without AVX-512 says so in the test log.
class TestRayAabbs : public ::testing::TestWithParam<simd::Kernel> {
 protected:
  void SetUp() override {
    if (const auto why = simd::unsupported_reason(GetParam())) GTEST_SKIP() << *why;
    forced_.emplace(GetParam());
    ASSERT_EQ(simd::selected(), GetParam());
  }
  std::optional<simd::ForcedKernel> forced_;
};

AabbSoa soa(std::initializer_list<Aabb> boxes) {
  AabbSoa s;
  for (const Aabb& b : boxes) s.push_back(b);
  return s;
}

TEST(AabbSoa, StoresTheBoxesByCoordinate) {
  const AabbSoa s = soa({{{1, 2, 3}, {4, 5, 6}}});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0], (Aabb{{1, 2, 3}, {4, 5, 6}}));
}

TEST_P(TestRayAabbs, TouchingIsAHit) {
  const AabbSoa boxes = soa({{{0, 0, 0}, {1, 1, 1}},       // corner to corner
                             {{1, 1, 1}, {2, 2, 2}},       // from its corner
                             {{2, 2.6, 0}, {3, 3, 1}},     // missed
                             {{-1, -1, -1}, {0, 0, 0}}});  // touched at the origin only
  std::vector<std::uint64_t> hits(1);
  EXPECT_EQ(test_ray_aabbs({{0, 0, 0}, {1, 1, 1}}, boxes, hits), 3u);
  EXPECT_EQ(bits_of(hits, 4), "1101");
  expect_same_as_scalar({{0, 0, 0}, {1, 1, 1}}, boxes);
}

TEST_P(TestRayAabbs, ParallelSlabsAreDecidedByTheOrigin) {
  const double outside = std::nextafter(1.0, 2.0);
  const AabbSoa boxes = soa({{{0, 0, 0}, {1, 1, 1}}, {{outside, 0, 0}, {2, 1, 1}}, {{-1, 0, 0}, {0, 1, 1}}});
  for (double dx : {0.0, -0.0, kDenormMin, -kDenormMin, 0x1p-1024, -0x1p-1024}) {
    std::vector<std::uint64_t> hits(1);
    EXPECT_EQ(test_ray_aabbs({{1, -1, 0.5}, {dx, 1, 0}}, boxes, hits), 1u);
    EXPECT_EQ(bits_of(hits, 3), "100");
    expect_same_as_scalar({{1, -1, 0.5}, {dx, 1, 0}}, boxes);
    expect_same_as_scalar({{0, -1, 0.5}, {dx, 1, 0}}, boxes);
  }
  // Parallel to all three slabs: a point test.
  expect_same_as_scalar({{1, 1, 1}, {0, 0, 0}}, boxes);
  expect_same_as_scalar({{outside, 1, 1}, {0, -0.0, 0}}, boxes);
}

TEST_P(TestRayAabbs, NaNAndInfinitiesGiveNoHit) {
  const AabbSoa boxes = soa({{{0, 0, 0}, {1, 1, 1}},
                             {{kNan, 0, 0}, {1, 1, 1}},
                             {{0, 0, 0}, {1, kNan, 1}},
                             {{-kInf, 0, 0}, {1, 1, 1}},
                             {{0, 0, 0}, {1, 1, kInf}},
                             {{1, 0, 0}, {0, 1, 1}}});  // inverted
  std::vector<std::uint64_t> hits(1);
  EXPECT_EQ(test_ray_aabbs({{-1, 0.5, 0.5}, {1, 0, 0}}, boxes, hits), 1u);
  EXPECT_EQ(bits_of(hits, 6), "100000");
  for (const Ray& ray : std::initializer_list<Ray>{{{kNan, 0.5, 0.5}, {1, 0, 0}},
                                                   {{-1, 0.5, 0.5}, {kNan, 0, 0}},
                                                   {{-1, 0.5, 0.5}, {kInf, 0, 0}},
                                                   {{-1, 0.5, 0.5}, {1, 0, 0}, kNan, kInf},
                                                   {{-1, 0.5, 0.5}, {1, 0, 0}, 0, kNan},
                                                   {{-1, 0.5, 0.5}, {1, 0, 0}, kInf, kInf},
                                                   {{-1, 0.5, 0.5}, {1, 0, 0}, -kInf, -kInf},
                                                   {{-1, 0.5, 0.5}, {1, 0, 0}, 2, 1}}) {
    EXPECT_EQ(expect_same_as_scalar(ray, boxes), 0u);
  }
  expect_same_as_scalar({{-1, 0.5, 0.5}, {1, 0, 0}, -kInf, kInf}, boxes);
}

TEST_P(TestRayAabbs, AComponentSubnormalOnceScaledTakesTheScalarPath) {
  // 2^-1000 against 1: scaled, it is 2^-1000 (normal), but 2^-1030 scaled stays subnormal.
  const AabbSoa boxes = soa({{{0, 0, 0}, {1, 1, 1}}, {{0, 2, 0}, {1, 3, 1}}});
  expect_same_as_scalar({{0.5, -1, 0.5}, {0x1p-1030, 1, 0}}, boxes);
  expect_same_as_scalar({{0.5, -1, 0.5}, {-0x1p-1070, 1, 0}}, boxes);
  expect_same_as_scalar({{0.5, -1, 0.5}, {0x1p-1000, 1, 0}}, boxes);
}

TEST_P(TestRayAabbs, TooFewHitWordsThrow) {
  AabbSoa boxes;
  for (int i = 0; i < 65; ++i) boxes.push_back({{0, 0, 0}, {1, 1, 1}});
  std::vector<std::uint64_t> hits(1);
  EXPECT_THROW(test_ray_aabbs({{0, 0, 0}, {1, 0, 0}}, boxes, hits), std::invalid_argument);
  hits.resize(hit_words(boxes.size()));
  EXPECT_EQ(test_ray_aabbs({{0, 0, 0}, {1, 0, 0}}, boxes, hits), 65u);
  EXPECT_EQ(hits, (std::vector<std::uint64_t>{~std::uint64_t{0}, 1}));
}

// Random rays and boxes whose coordinates come from a small set of values, so that ties,
// touching, parallel slabs and special values are frequent; every batch length from 0 to 40
// exercises the vector blocks and the remainder.
TEST_P(TestRayAabbs, AgreesWithTheScalarTestOnRandomSpecialValues) {
  const double values[] = {0,   -0.0, 1, -1, 0.5, 2, 3, -3, 1e-300, -1e-300, 1e300, -1e300, kDenormMin, -kDenormMin,
                           DBL_MIN, 0x1p-1024, std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), 0.1, kNan, kInf,
                           -kInf};
  std::mt19937_64 rng(20261121);
  const auto pick = [&](bool special) {
    const std::size_t n = special ? std::size(values) : std::size(values) - 3;
    return values[rng() % n];
  };
  std::size_t total_hits = 0;
  for (int round = 0; round < 400; ++round) {
    const bool special = round % 4 == 0;
    Ray ray{{pick(special), pick(special), pick(special)}, {pick(special), pick(special), pick(special)}};
    if (round % 3 == 0) ray.tmin = pick(special), ray.tmax = round % 2 ? kInf : pick(special);
    AabbSoa boxes;
    for (int i = 0; i < round % 41; ++i) {
      Aabb b{{pick(special), pick(special), pick(special)}, {pick(special), pick(special), pick(special)}};
      for (int a = 0; a < 3; ++a) {
        if (i % 5 != 0 && b.lo[a] > b.hi[a]) std::swap(b.lo[a], b.hi[a]);  // mostly valid boxes
      }
      boxes.push_back(b);
    }
    total_hits += expect_same_as_scalar(ray, boxes);
  }
  EXPECT_GT(total_hits, 100u);  // the comparison is not only among misses
}

// Generic rays against boxes around them: the common case of the vector path, with hits and
// near misses; a box is sometimes made to touch the ray at its entry point.
TEST_P(TestRayAabbs, AgreesWithTheScalarTestOnGenericRays) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t total_hits = 0;
  for (int round = 0; round < 200; ++round) {
    const Ray ray{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, round % 2 ? 0 : -kInf, round % 3 ? kInf : 2};
    AabbSoa boxes;
    for (int i = 0; i < 67; ++i) {
      const Vec3 c{2 * u(rng), 2 * u(rng), 2 * u(rng)};
      const Vec3 h{0.3 * std::fabs(u(rng)), 0.3 * std::fabs(u(rng)), 0.3 * std::fabs(u(rng))};
      Aabb b{c - h, c + h};
      if (i % 7 == 0) {  // a face through a point of the ray
        const Vec3 p = ray.origin + 0.75 * ray.dir;
        b.lo.x = p.x;
        b.hi.x = std::max(b.hi.x, p.x);
      }
      boxes.push_back(b);
    }
    total_hits += expect_same_as_scalar(ray, boxes);
  }
  EXPECT_GT(total_hits, 100u);
}

// Special boxes at every place of batches of 1 to 19 boxes, so that each one is met in every
// lane of a vector block and at every place of the scalar tail (19 = 2 * 8 + 3 = 4 * 4 + 3),
// the other places holding the other special boxes; against special rays: parallel slabs
// (0, -0, subnormal), a ray along a face, infinite ends, NaN.
TEST_P(TestRayAabbs, SpecialBoxesAgreeInEveryLaneAndInTheTail) {
  const double above = std::nextafter(1.0, 2.0);
  const std::vector<Aabb> special = {{{0, 0, 0}, {1, 1, 1}},
                                     {{1, 1, 1}, {2, 2, 2}},            // touched at a corner
                                     {{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}},  // a point box
                                     {{above, 0, 0}, {2, 1, 1}},        // one ulp past a face
                                     {{-0.0, -0.0, -0.0}, {0, 0, 0}},
                                     {{kNan, 0, 0}, {1, 1, 1}},
                                     {{0, 0, 0}, {1, 1, kInf}},
                                     {{-kInf, 0, 0}, {1, 1, 1}},
                                     {{1, 0, 0}, {0, 1, 1}},            // inverted
                                     {{-3, -3, -3}, {-2, -2, -2}},
                                     {{0, 0, 0}, {kDenormMin, kDenormMin, kDenormMin}}};
  const std::vector<Ray> rays = {{{0, 0, 0}, {1, 1, 1}},
                                 {{1, -1, 0.5}, {0, 1, 0}},               // parallel to x on the face x = 1
                                 {{1, -1, 0.5}, {-0.0, 1, -0.0}},
                                 {{0.5, -1, 0.5}, {kDenormMin, 1, 0}},    // subnormal: the scalar path
                                 {{0, 0.5, 0.5}, {1, 0, 0}, -kInf, kInf}, // a line along a face
                                 {{2, 2, 2}, {-1, -1, -1}, 0, 1},         // a segment ending at the corner
                                 {{0.25, 0.25, 0.25}, {0, 0, 0}},         // a point
                                 {{kNan, 0, 0}, {1, 0, 0}},
                                 {{0, 0, 0}, {1, 1, 1}, kInf, kInf}};
  std::size_t hits = 0, runs = 0;
  for (const Ray& ray : rays) {
    for (std::size_t n = 1; n <= 19; ++n) {
      for (std::size_t at = 0; at < n; ++at) {
        for (std::size_t s = 0; s < special.size(); ++s) {
          AabbSoa boxes;
          for (std::size_t i = 0; i < n; ++i) boxes.push_back(special[(s + (i == at ? 0 : 1 + i)) % special.size()]);
          hits += expect_same_as_scalar(ray, boxes);
          ++runs;
        }
      }
    }
  }
  EXPECT_GT(hits, runs);  // hits are common, not only misses
}

INSTANTIATE_TEST_SUITE_P(EveryKernel, TestRayAabbs, ::testing::ValuesIn(simd::kAllKernels),
                         [](const ::testing::TestParamInfo<simd::Kernel>& p) { return std::string(simd::to_string(p.param)); });

}  // namespace
}  // namespace cc
