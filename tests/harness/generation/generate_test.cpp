// The generators meet the boundary: touching (exact margin 0), parallel and degenerate
// configurations for every kind, touching rays and balls at generic values where floating point
// rounds either way of the boundary, and inputs outside the domain when asked.
#include "harness/generation/generate.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "harness/judging/features.h"
#include "harness/generation/triangles.h"
#include "harness/formats/input_json.h"
#include "oracle/exact/exact_reference.h"
#include "case_budget.h"
#include "test_paths.h"

namespace cc::harness {
namespace {

const GenerateOptions kOptions{.mesh_folder = test::fcl_mesh_folder()};

TEST(Generate, IsDeterministic) {
  for (QueryKind kind : kAllQueryKinds) {
    RandomChoices a(9), b(9);
    EXPECT_EQ(input_to_json(generate(kind, a, kOptions)).dump(), input_to_json(generate(kind, b, kOptions)).dump());
  }
}

TEST(Generate, ZeroChoicesGiveASimpleCaseInTheDomain) {
  const exact::ExactRationalReference exact;
  for (QueryKind kind : kAllQueryKinds) {
    ReplayChoices zeros({});
    const ExactVerdict v = exact.judge(generate(kind, zeros, kOptions));
    EXPECT_EQ(v.contract, Contract::in) << name(kind) << ": " << v.note;
  }
}

TEST(Generate, MeetsTouchingParallelAndDegenerateCases) {
  const exact::ExactRationalReference exact;
  for (QueryKind kind : kAllQueryKinds) {
    int touching = 0, parallel = 0, degenerate = 0, hits = 0, misses = 0;
    const int n = test::case_budget(kind, 2000);
    for (int i = 0; i < n; ++i) {
      RandomChoices c(static_cast<std::uint64_t>(i));
      const Input input = generate(kind, c, kOptions);
      const ExactVerdict v = exact.judge(input);
      const Features f = features_of(input, v);
      touching += f.touching;
      parallel += f.parallel;
      degenerate += f.degenerate;
      if (v.contract == Contract::in) (v.answer.hit ? hits : misses) += 1;
    }
    EXPECT_GT(touching, n / 50) << name(kind);
    if (parallel_applies(kind)) {
      EXPECT_GT(parallel, n / 50) << name(kind);
    }
    EXPECT_GT(degenerate, n / 50) << name(kind);
    EXPECT_GT(hits, n / 10) << name(kind);
    EXPECT_GT(misses, n / 10) << name(kind);
  }
}

// Exact hits (in contract) of generated cases of `kind` for which `rounds_apart` holds, out of n.
template <typename In, typename Pred>
int exact_hits_where(QueryKind kind, int n, Pred rounds_apart) {
  const exact::ExactRationalReference exact;
  int count = 0;
  for (int i = 0; i < n; ++i) {
    RandomChoices c(static_cast<std::uint64_t>(i));
    const Input input = generate(kind, c, kOptions);
    const ExactVerdict v = exact.judge(input);
    count += v.contract == Contract::in && v.decided && v.answer.hit && rounds_apart(std::get<In>(input));
  }
  return count;
}

// Segments that hit, though an end of theirs lies past a slab parameter as computed in
// floating point without a rounding bound: the end within an ULP of the boundary, where the
// parameter rounds either way of it.
TEST(Generate, RayAabbMeetsSegmentEndsWhereTheSlabParameterRoundsPastThem) {
  const int n = 4000;
  const int count = exact_hits_where<RayAabbInput>(QueryKind::ray_aabb, n, [](const RayAabbInput& in) {
    const Ray& r = in.ray;
    for (int k = 0; k < 3; ++k) {
      if (!(std::fabs(r.dir[k]) >= DBL_MIN)) continue;
      const double inv = 1.0 / r.dir[k];
      const double near = ((r.dir[k] > 0 ? in.box.lo[k] : in.box.hi[k]) - r.origin[k]) * inv;
      const double far = ((r.dir[k] > 0 ? in.box.hi[k] : in.box.lo[k]) - r.origin[k]) * inv;
      if (near > r.tmax || far < r.tmin) return true;
    }
    return false;
  });
  EXPECT_GT(count, n / 400);
}

// Touching or overlapping balls whose squared distance, as computed, exceeds their squared
// reach: generic scales, where the squares round either way of each other.
TEST(Generate, SphereSphereMeetsTouchingBallsWhoseSquaresRoundApart) {
  const int n = 2000;
  const int count = exact_hits_where<SphereSphereInput>(QueryKind::sphere_sphere, n, [](const SphereSphereInput& in) {
    const Vec3 d = in.a.center - in.b.center;
    const double reach = in.a.radius + in.b.radius;
    return d.x * d.x + d.y * d.y + d.z * d.z > reach * reach;
  });
  EXPECT_GT(count, n / 100);
}

// One vertex on the box's boundary or a few ULPs off it on one axis, whichever axis is nudged:
// each of its coordinates within 4 ULPs of the box's range on that axis. (The box's ranges are
// far apart, so a coordinate nudged from another axis's value lies far outside.)
TEST(Generate, ATriangleTouchingAtAVertexIsOnTheBoundaryOrJustOffIt) {
  const Aabb box{{100, -7, 3}, {101, -6, 4}};
  const auto within_ulps = [](double x, double lo, double hi) {
    double low = lo, high = hi;
    for (int i = 0; i < 4; ++i) low = std::nextafter(low, -INFINITY), high = std::nextafter(high, INFINITY);
    return x >= low && x <= high;
  };
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    RandomChoices c(seed);
    ValueSource values(c, {});
    const Triangle t = triangle_touching_at_a_vertex(values, box);
    int near = 0;
    for (const Vec3& p : t.v) {
      bool on = true;
      for (int k = 0; k < 3; ++k) on &= within_ulps(p[k], box.lo[k], box.hi[k]);
      near += on;
    }
    ASSERT_GE(near, 1) << "seed " << seed << ": no vertex on or just off the box: " << input_to_json(TriAabbInput{t, box}).dump();
  }
}

TEST(Generate, OutOfContractCasesLeaveTheDomain) {
  const exact::ExactRationalReference exact;
  for (QueryKind kind : kAllQueryKinds) {
    int outside = 0;
    const int n = test::case_budget(kind, 500);
    for (int i = 0; i < n; ++i) {
      RandomChoices c(static_cast<std::uint64_t>(i));
      outside += exact.judge(generate(kind, c, {.out_of_contract = true, .mesh_folder = test::fcl_mesh_folder()})).contract != Contract::in;
    }
    EXPECT_GT(outside, n / 20) << name(kind);
  }
}

}  // namespace
}  // namespace cc::harness
