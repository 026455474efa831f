// The tri_obb_distance kind's unit: its answer (the signed distance, the witnesses and their
// bounds), its exact verdict apart, overlapping and touching, how a witness off its shape is
// judged, its generator's gaps and parallel features, and its domain.
#include "harness/kinds/tri_obb_distance.h"

#include <gtest/gtest.h>

#include "harness/generation/generate.h"
#include "harness/judging/classify.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

using Kind = Query<TriObbDistanceInput>;

const Obb kUnitBox{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
Triangle tri(const Vec3& a, const Vec3& b, const Vec3& c) { return {{a, b, c}}; }
// A vertex 0.75 above the top face; a vertex 0.125 into it; a vertex on it.
const TriObbDistanceInput kApart{tri({0.25, 0.5, 1.75}, {3, 3, 5}, {-2, 2, 6}), kUnitBox};
const TriObbDistanceInput kOverlapping{tri({0.25, 0.25, 0.875}, {4, 1, 6}, {1, 4, 6}), kUnitBox};
const TriObbDistanceInput kTouching{tri({0, 0, 1}, {3, 0, 3}, {0, 3, 3}), kUnitBox};

TEST(TriObbDistanceKind, TheAnswerIsTheSignedDistanceTheWitnessesAndTheirBounds) {
  const Answer apart = Kind::ask(kApart);
  EXPECT_FALSE(apart.hit);
  ASSERT_EQ(apart.params.size(), 9u);
  EXPECT_NEAR(apart.params[0], 0.75, 1e-12);
  EXPECT_NEAR(apart.params[3], 1.75, 1e-15);  // on the triangle's vertex
  EXPECT_NEAR(apart.params[6], 1, 1e-15);     // on the box's top face
  const Answer overlapping = Kind::ask(kOverlapping);
  EXPECT_TRUE(overlapping.hit);
  EXPECT_NEAR(overlapping.params[0], -0.125, 1e-12);
  EXPECT_GT(overlapping.params[7], 0);  // the distance's bound
  EXPECT_EQ(ask_library(Input{kOverlapping}), overlapping);
}

TEST(TriObbDistanceKind, TheExactVerdictIsSignedAndItsWitnessesAreOnTheShapes) {
  const exact::ExactRationalReference exact;
  const std::pair<const TriObbDistanceInput*, double> cases[] = {{&kApart, 0.75}, {&kOverlapping, -0.125}, {&kTouching, 0}};
  for (const auto& [in, distance] : cases) {
    const ExactVerdict v = exact.judge(Input{*in});
    ASSERT_EQ(v.contract, Contract::in);
    EXPECT_EQ(v.answer.hit, distance <= 0);
    EXPECT_EQ(v.answer.params, std::vector<double>{distance});
    EXPECT_EQ(classify(QueryKind::tri_obb_distance, Kind::ask(*in), v, {}).cls, CaseClass::agree) << distance;
  }
  // The box's witness of the overlap must lie on its boundary: its centre is 1 from it, far
  // beyond the bound.
  const ExactVerdict v = exact.judge(Input{kOverlapping});
  Answer overlapping = Kind::ask(kOverlapping);
  overlapping.params[4] = 0, overlapping.params[5] = 0, overlapping.params[6] = 0;
  const Verdict w = classify(QueryKind::tri_obb_distance, overlapping, v, {});
  EXPECT_EQ(w.cls, CaseClass::impl_bug);
  EXPECT_NE(w.parties[0].why.find("on_b lies"), std::string::npos) << w.parties[0].why;
}

// The generator reaches every sign, both sides of touching by a hair, gaps and depths from a few
// ulps to half the size, and triangles with an edge or their plane parallel to a face, touching and
// at a gap or a depth away from it (closest points not unique, a depth on a face).
TEST(TriObbDistanceKind, TheGeneratorMeetsEverySideOfTouching) {
  const exact::ExactRationalReference exact;
  int apart = 0, overlapping = 0, touching = 0, hair = 0, parallel_edge = 0, parallel_face = 0;
  int parallel_apart = 0, parallel_deep = 0;
  int near[2] = {}, far[2] = {};  // |d| in [2^-61, 2^-31) and [2^-31, 2^-1) of the size: overlapping, apart
  for (std::uint64_t i = 0; i < 800; ++i) {
    RandomChoices c(i);
    const Input input = generate(QueryKind::tri_obb_distance, c);
    const auto& in = std::get<TriObbDistanceInput>(input);
    const ExactVerdict v = exact.judge(input);
    if (v.contract != Contract::in || !v.decided) continue;
    const double d = v.answer.params.at(0);
    apart += d > 0, overlapping += d < 0, touching += d == 0;
    double size = max_abs(in.box.half);
    for (int k = 0; k < 3; ++k) size = std::max(size, max_abs(in.tri.v[k] - in.tri.v[(k + 1) % 3]));
    hair += d != 0 && std::fabs(d) < 0x1p-30 * size;
    const double a = std::fabs(d);
    near[d > 0] += a >= std::ldexp(size, -61) && a < std::ldexp(size, -31);
    far[d > 0] += a >= std::ldexp(size, -31) && a < std::ldexp(size, -1);
    // Heights of the vertices along each box axis: two or three equal is an edge or the plane
    // parallel to a face (to the rounding of the placement).
    for (const Vec3& axis : in.box.axes.col) {
      int equal = 0;
      for (int k = 0; k < 3; ++k) {
        equal += std::fabs(dot(in.tri.v[k] - in.tri.v[(k + 1) % 3], axis)) <= 0x1p-40 * size;
      }
      parallel_edge += equal == 1, parallel_face += equal == 3;
      if (equal >= 1 && std::fabs(d) > 0x1p-20 * size) (d > 0 ? parallel_apart : parallel_deep) += 1;
    }
  }
  EXPECT_GT(apart, 50);
  EXPECT_GT(overlapping, 50);
  EXPECT_GT(touching, 10);
  EXPECT_GT(hair, 10);
  for (int side : {0, 1}) {
    EXPECT_GT(near[side], 20) << side;
    EXPECT_GT(far[side], 20) << side;
  }
  EXPECT_GT(parallel_edge, 20);
  EXPECT_GT(parallel_face, 20);
  EXPECT_GT(parallel_apart, 20);
  EXPECT_GT(parallel_deep, 20);
}

TEST(TriObbDistanceKind, TheDomainReachesFrom0To2To500) {
  const exact::ExactRationalReference exact;
  const auto scaled = [](double s) {
    TriObbDistanceInput in = kApart;
    for (Vec3& p : in.tri.v) p = s * p;
    in.box.center = s * in.box.center, in.box.half = s * in.box.half;
    return Input{in};
  };
  EXPECT_EQ(exact.judge(scaled(0x1p-1000)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p400)).contract, Contract::in);
  EXPECT_EQ(exact.judge(scaled(0x1p600)).contract, Contract::unspecified);
  TriObbDistanceInput skewed = kApart;
  skewed.box.axes.col[0].y = 0x1p-20;  // far beyond the orthonormality tolerance
  EXPECT_EQ(exact.judge(Input{skewed}).contract, Contract::unspecified);
  for (double s : {0x1p-1000, 0x1p400}) {
    EXPECT_EQ(classify(QueryKind::tri_obb_distance, ask_library(scaled(s)), exact.judge(scaled(s)), {}).cls, CaseClass::agree);
  }
}

}  // namespace
}  // namespace cc::harness
