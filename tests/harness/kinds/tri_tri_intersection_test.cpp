// The tri_tri_intersection kind's unit: its answer (the hit and the corners as params), its case
// files, its exact verdict (the corners, their tolerance), how a wrong corner is judged, and what
// its generator makes.
#include "harness/kinds/tri_tri_intersection.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "harness/formats/input_json.h"
#include "harness/generation/generate.h"
#include "harness/judging/classify.h"
#include "harness/judging/configurations.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

using Kind = Query<TriTriIntersectionInput>;

const Triangle kBase{{Vec3{0, 0, 0}, Vec3{4, 0, 0}, Vec3{0, 4, 0}}};
// Standing across kBase along x = 1, from y = 0 to y = 2.
const TriTriIntersectionInput kCrossing{kBase, {{Vec3{1, -1, -1}, Vec3{1, 3, 1}, Vec3{1, -1, 1}}}};

TEST(TriTriIntersectionKind, TheAnswerIsTheHitAndTheCorners) {
  const Answer a = Kind::ask(kCrossing);
  EXPECT_TRUE(a.hit);
  ASSERT_EQ(a.params.size(), 6u);
  std::vector<double> sorted = a.params;
  if (sorted[1] > sorted[4]) std::swap_ranges(sorted.begin(), sorted.begin() + 3, sorted.begin() + 3);
  EXPECT_EQ(sorted, (std::vector<double>{1, 0, 0, 1, 1, 0}));
  EXPECT_EQ(Kind::ask({kBase, {{Vec3{1, 1, 1}, Vec3{2, 1, 1}, Vec3{1, 2, 1}}}}), Answer::of(false));
  EXPECT_EQ(ask_library(Input{kCrossing}), a);
}

TEST(TriTriIntersectionKind, CaseFilesAreReadable) {
  EXPECT_EQ(input_to_json(kCrossing).dump(),
            R"({"a":[["0","0","0"],["4","0","0"],["0","4","0"]],"b":[["1","-1","-1"],["1","3","1"],["1","-1","1"]]})");
  EXPECT_TRUE(input_from_json(QueryKind::tri_tri_intersection, input_to_json(kCrossing), "/inputs") == Input{kCrossing});
}

TEST(TriTriIntersectionKind, TheExactVerdictGivesTheCornersAndTheirTolerance) {
  const exact::ExactRationalReference exact;
  const ExactVerdict v = exact.judge(Input{kCrossing});
  EXPECT_TRUE(v.answer.hit);
  EXPECT_EQ(v.answer.params.size(), 6u);
  // The largest kappa: at (1, 1, 0), b's edge (0, 4, 2) crosses a's plane at sin phi = 1 / sqrt 5,
  // times a's L^2 / |n| = 32 / 16: 2 sqrt 5 = 4.47. M = 4; and 2^-48 M for judging in doubles.
  EXPECT_GT(v.corner_tolerance, 0x1p-44 * 4 * 4.4);
  EXPECT_LT(v.corner_tolerance, 0x1p-44 * 4 * 4.8);
  // The right corners agree; one moved by a thousand times the tolerance is an impl_bug.
  EXPECT_EQ(classify(QueryKind::tri_tri_intersection, Kind::ask(kCrossing), v, {}).cls, CaseClass::agree);
  Answer moved = Kind::ask(kCrossing);
  moved.params[1] += 1000 * v.corner_tolerance;
  const Verdict wrong = classify(QueryKind::tri_tri_intersection, moved, v, {});
  EXPECT_EQ(wrong.cls, CaseClass::impl_bug);
  EXPECT_NE(wrong.parties[0].why.find("from the exact ones"), std::string::npos) << wrong.parties[0].why;
  // A corner dropped (the segment's end) is as wrong: the exact end is far from the hull.
  Answer dropped = Kind::ask(kCrossing);
  dropped.params.resize(3);
  EXPECT_EQ(classify(QueryKind::tri_tri_intersection, dropped, v, {}).cls, CaseClass::impl_bug);
  // Corners without a hit, or a hit without them, are judged on the hit.
  EXPECT_EQ(classify(QueryKind::tri_tri_intersection, Answer::of(true), v, {}).cls, CaseClass::agree);
  EXPECT_EQ(classify(QueryKind::tri_tri_intersection, Answer::of(false), v, {}).cls, CaseClass::impl_bug);
}

TEST(TriTriIntersectionKind, TheGeneratorMakesEveryConfiguration) {
  const exact::ExactRationalReference exact;
  std::vector<std::string_view> seen;
  RandomChoices c(11);
  const GenerateOptions options{.exact = &exact};
  for (int i = 0; i < 3000; ++i) {
    const Input in = generate(QueryKind::tri_tri_intersection, c, options);
    for (std::string_view name : configurations_of(in, exact.judge(in))) {
      if (std::find(seen.begin(), seen.end(), name) == seen.end()) seen.push_back(name);
    }
  }
  for (std::string_view name : Kind::configurations()) {
    EXPECT_NE(std::find(seen.begin(), seen.end(), name), seen.end()) << name;
  }
}

}  // namespace
}  // namespace cc::harness
