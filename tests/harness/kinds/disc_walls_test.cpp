// The disc_walls kind's unit: its answers (the walls touched, by both methods), its case files'
// layout, its touching construction, features and configurations, and what its generator makes.
#include "harness/kinds/disc_walls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "harness/formats/input_json.h"
#include "harness/generation/generate.h"
#include "harness/generation/values.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"
#include "harness/model/library.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

using Kind = Query<DiscWallsInput>;

bool has(const std::vector<std::string_view>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<std::string_view> configurations(const DiscWallsInput& in) {
  static const exact::ExactRationalReference exact;
  return configurations_of(in, exact.judge(in));
}

// A disc of radius 0.5 at (1, 0.5): the floor touched at its side, a pillar at (1, 1) touched,
// a wall along x at y = 2 apart, a wall ending at (1.5, 0.5) touched at its end.
const DiscWallsInput kRoom{{{1, 0.5}, 0.5}, {{{0, 0}, {2, 0}}, {{1, 1}, {1, 1}}, {{0, 2}, {2, 2}}, {{3, 0.5}, {1.5, 0.5}}}};

TEST(DiscWallsKind, TheAnswerIsTheWallsTouchedByEachMethod) {
  const Answer a = Kind::ask(kRoom);
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.pairs, (std::vector<FacePair>{{0, 0}, {1, 0}, {3, 0}}));
  const std::vector<Opinion> others = ask_parties(Kind::library_parties(), kRoom);
  ASSERT_EQ(others.size(), 1u);
  EXPECT_EQ(others[0].party, "library.disc_walls(point_against_grown_walls)");
  EXPECT_EQ(others[0].status, Opinion::Status::answered);
  EXPECT_EQ(others[0].answer, a);
  EXPECT_EQ(Kind::ask({{{1, 5}, 0.5}, kRoom.walls}), Answer::of(false));
  EXPECT_EQ(Kind::ask({{{1, 0.5}, -0.5}, kRoom.walls}), Answer::of(false));  // out of contract: nothing touched
  EXPECT_EQ(ask_library(Input{kRoom}), a);
}

TEST(DiscWallsKind, CaseFilesAreReadable) {
  const DiscWallsInput in{{{1, 2}, 0.5}, {{{0, 0}, {3, 0}}, {{-0.0, INFINITY}, {0.25, 0.25}}}};
  EXPECT_EQ(input_to_json(in).dump(),
            R"({"disc":{"center":["1","2"],"radius":"0.5"},"walls":[{"a":["0","0"],"b":["3","0"]},)"
            R"({"a":["-0","inf"],"b":["0.25","0.25"]}]})");
  EXPECT_TRUE(input_from_json(QueryKind::disc_walls, input_to_json(in), "/inputs") == Input{in});
}

TEST(DiscWallsKind, TouchPutsTheDiscAtTheRadiusFromAnEnd) {
  const exact::ExactRationalReference exact;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    RandomChoices c(seed);
    ValueSource values(c, {});
    DiscWallsInput in{{{7, -3}, 0.75}, {{{0, 0}, {0, 4}}, {{1, 1}, {1, 1}}}};
    Kind::touch(in, values);
    const ExactVerdict v = exact.judge(in);
    EXPECT_TRUE(v.answer.hit) << input_to_json(in).dump();
    EXPECT_EQ(v.margin, 0) << input_to_json(in).dump();
  }
}

TEST(DiscWallsKind, FeaturesAreParallelAndDegenerateWalls) {
  EXPECT_TRUE(Kind::features(kRoom).parallel);  // walls along x
  EXPECT_TRUE(Kind::features(kRoom).degenerate);  // the pillar
  const DiscWallsInput slanted{{{0, 0}, 1}, {{{0, 0}, {1, 2}}, {{5, 0}, {6, 3}}}};
  EXPECT_FALSE(Kind::features(slanted).parallel);
  EXPECT_FALSE(Kind::features(slanted).degenerate);
  EXPECT_TRUE(Kind::features({{{0, 0}, 0}, slanted.walls}).degenerate);  // a point disc
  EXPECT_TRUE(Kind::features({{{0, 0}, 1}, {{{0, 0}, {1, 2}}, {{5, 0}, {7, 4}}}}).parallel);  // parallel walls
}

TEST(DiscWallsKind, ConfigurationsComeFromTheWallsAndTheExactMargins) {
  auto names = configurations(kRoom);
  for (std::string_view n : {"touching", "touching a side", "touching at an end", "pillar"}) EXPECT_TRUE(has(names, n)) << n;
  EXPECT_FALSE(has(names, "walls sharing an end"));
  // A corner (walls sharing an end), a point disc on it, far from the origin.
  const Vec2 corner{0x1p30, -0x1p30};
  names = configurations({{corner, 0}, {{corner, {0x1p30 + 1, -0x1p30}}, {corner, {0x1p30, -0x1p30 + 1}}}});
  for (std::string_view n : {"touching", "touching at an end", "walls sharing an end", "point disc", "far from the origin"}) {
    EXPECT_TRUE(has(names, n)) << n;
  }
  // A corridor of nearly parallel walls, the disc apart from both by 2^-45 of the scale 64.
  names = configurations({{{1, 0.5}, 0.5 - 0x1p-39}, {{{0, 0}, {64, 0}}, {{0, 1}, {64, 1 + 0x1p-30}}}});
  for (std::string_view n : {"just apart", "nearly parallel walls"}) EXPECT_TRUE(has(names, n)) << n;
  EXPECT_FALSE(has(names, "touching"));
  EXPECT_TRUE(has(configurations({{{0x1p-200, 0}, 0x1p-201}, {{{0, 0}, {0, 0x1p-200}}}}), "tiny scale"));
  EXPECT_TRUE(has(configurations({{{0x1p200, 0}, 0x1p199}, {{{0, 0}, {0, 0x1p200}}}}), "huge scale"));
}

// Without the exact reference (no bisection) the grid constructions alone touch exactly: at a
// side, at an end or a pillar, as a point; and out of contract when asked.
TEST(DiscWallsKind, TheGeneratorTouchesExactlyByConstruction) {
  const exact::ExactRationalReference exact;
  const int n = 2000;
  int side = 0, end = 0, point = 0, outside = 0;
  for (int i = 0; i < n; ++i) {
    RandomChoices c(static_cast<std::uint64_t>(i));
    const Input in = generate(QueryKind::disc_walls, c);
    const auto names = configurations_of(in, exact.judge(in));
    side += has(names, "touching a side");
    end += has(names, "touching at an end");
    point += has(names, "point disc") && has(names, "touching");
    RandomChoices d(static_cast<std::uint64_t>(i));
    outside += exact.judge(generate(QueryKind::disc_walls, d, {.out_of_contract = true})).contract != Contract::in;
  }
  EXPECT_GT(side, n / 50);
  EXPECT_GT(end, n / 50);
  EXPECT_GT(point, n / 100);
  EXPECT_GT(outside, n / 20);
}

}  // namespace
}  // namespace cc::harness
