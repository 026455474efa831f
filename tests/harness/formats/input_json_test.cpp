#include "harness/formats/input_json.h"

#include <gtest/gtest.h>
#include "test_paths.h"

#include <cmath>
#include <cstring>

#include "harness/generation/choices.h"
#include "harness/generation/generate.h"

namespace cc::harness {
namespace {

bool same_bits(const Json& a, const Json& b) { return a.dump() == b.dump(); }

TEST(InputJson, EveryKindRoundTripsBitForBit) {
  for (QueryKind kind : kAllQueryKinds) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
      RandomChoices choices(seed);
      const Input input = generate(kind, choices, {.out_of_contract = true, .mesh_folder = test::fcl_mesh_folder()});
      const Json json = input_to_json(input);
      const Input back = input_from_json(kind, json, "/inputs", test::corpus_case_folder());
      ASSERT_TRUE(same_bits(input_to_json(back), json)) << name(kind) << " " << json.dump();
    }
  }
}

TEST(InputJson, SpecialValuesAreSpelledOut) {
  const Json j = input_to_json(SphereSphereInput{{{-0.0, NAN, INFINITY}, 5e-324}, {{0.1, 0, 0}, 1}});
  EXPECT_EQ(j["a"]["center"].dump(), R"(["-0","nan","inf"])");
  EXPECT_EQ(j["a"]["radius"], "5e-324");
}

void expect_error(QueryKind kind, const char* text, const std::string& pointer, const std::string& fragment) {
  try {
    input_from_json(kind, Json::parse(text), "/inputs");
    ADD_FAILURE() << "no error for " << text;
  } catch (const FormatError& e) {
    EXPECT_EQ(e.pointer(), pointer) << text;
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(InputJson, ErrorsNameThePlace) {
  expect_error(QueryKind::sphere_sphere, R"({"a": {"center": ["0","0","0"], "radius": "1"}})", "/inputs",
               "missing field \"b\"");
  expect_error(QueryKind::sphere_sphere,
               R"({"a": {"center": ["0","0","0"], "radius": "1"}, "b": {"center": ["0","1x","0"], "radius": "1"}})",
               "/inputs/b/center/1", "\"1x\" is not a number");
  expect_error(QueryKind::aabb_aabb, R"({"a": {"lo": [0, 0], "hi": [1, 1, 1]}, "b": {"lo": [0,0,0], "hi": [1,1,1]}})",
               "/inputs/a/lo", "expected an array of 3 numbers");
  expect_error(QueryKind::kdop_kdop, R"({"k": 12, "a": [], "b": []})", "/inputs/k", "k must be one of");
  expect_error(QueryKind::tri_tri, R"({"a": [["0","0","0"]], "b": []})", "/inputs/a", "expected 3 vertices");
  expect_error(QueryKind::ray_aabb, R"([1, 2])", "/inputs", "expected an object");
  expect_error(QueryKind::disc_walls, R"({"disc": {"center": ["0"], "radius": "1"}, "walls": []})", "/inputs/disc/center",
               "expected an array of 2 numbers");
  expect_error(QueryKind::disc_walls, R"({"disc": {"center": [0, 0], "radius": 1}, "walls": {"a": [0, 0]}})", "/inputs/walls",
               "expected an array of objects");
  expect_error(QueryKind::disc_walls, R"({"disc": {"center": [0, 0], "radius": 1}, "walls": [{"a": [0, 0]}]})",
               "/inputs/walls/0", "missing field \"b\"");
}

TEST(InputJson, AcceptsPlainJsonNumbers) {
  const Input in = input_from_json(QueryKind::aabb_aabb, Json::parse(R"({"a": {"lo": [0, 0, 0], "hi": [1, 1, 1]},
      "b": {"lo": [0.5, 0.5, 0.5], "hi": [2, 2, 2]}})"), "/inputs");
  EXPECT_EQ(std::get<AabbAabbInput>(in).b.lo.x, 0.5);
}

}  // namespace
}  // namespace cc::harness
