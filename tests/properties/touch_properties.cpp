// The touching constructions (harness/generation/touch.h and each kind's Query<In>::touch), as the
// fuzzers' custom mutator uses them: a generated case of every kind, in contract or not, moved so
// that its second shape touches the first. In exact arithmetic the moved case is never apart by
// more than the constructions' rounding: its exact margin (relative to the inputs' scale, < 0
// apart) is at least -kRounding. Where the construction puts a face, a corner or a vertex against
// the other shape with nothing of it beyond (kTouchingOnly), it is not overlapping by more either:
// |margin| <= kRounding. Each kind must also meet touching cases (|margin| within kRounding) and
// cases whose exact margin is 0, so a construction that misses by a whole term is seen, and one
// that stops being called is too.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>

#include "harness/formats/input_json.h"
#include "harness/formats/number_text.h"
#include "harness/generation/generate.h"
#include "harness/generation/touch.h"
#include "harness/model/mesh_query.h"
#include "oracle/exact/exact_reference.h"
#include "case_budget.h"
#include "properties/property.h"
#include "test_paths.h"

namespace cc::test {
namespace {

using namespace harness;

// The constructions round a few times (a pose applied to a vertex, a point moved back along a
// direction of up to 2^4 times its length, a frame's columns times a local point): each rounding
// is at most 2^-53 of the largest value it involves, which the margin's scale bounds up to a
// factor of 2^4. 2^-40 leaves those and a few hundred more.
constexpr double kRounding = 0x1p-40;

// The kinds whose shapes, moved to touch, touch without overlapping: balls, boxes and k-DOPs
// face to face or corner on face; meshes vertex on vertex, broadphase boxes face to face, a disc
// against a wall's end, a segment ending on a mesh's vertex (each kind's margin is its pair, box
// or wall nearest contact). In the others a shape may reach through: a ray aimed at a point of a
// box's boundary, a triangle with one vertex put on the other shape, boxes that touch at the
// middle of their motion.
constexpr QueryKind kTouchingOnly[] = {QueryKind::sphere_sphere, QueryKind::aabb_aabb,  QueryKind::kdop_kdop,
                                       QueryKind::obb_obb,       QueryKind::mesh_mesh,  QueryKind::mesh_mesh_first,
                                       QueryKind::broadphase,    QueryKind::ray_mesh,   QueryKind::disc_walls};

class Touch : public ::testing::TestWithParam<QueryKind> {};

TEST_P(Touch, MovedToTouchIsNeverApart) {
  const QueryKind kind = GetParam();
  const exact::ExactRationalReference exact;
  const bool touching_only = std::ranges::find(kTouchingOnly, kind) != std::end(kTouchingOnly);
  const std::string property =
      std::string(name(kind)) + " moved to touch is never apart" + (touching_only ? " nor overlapping" : "");
  int judged = 0, touching = 0, exactly = 0;
  const bool passed = check_property_with_choices(property, case_budget(kind, 1500), [&](Choices& choices) {
    GenerateOptions options;
    // A fifth of the cases without FCL's test meshes, as a user's machine without them draws
    // them: procedural meshes only.
    options.mesh_folder = choices.chance(20) ? fcl_mesh_folder() / "absent" : fcl_mesh_folder();
    options.out_of_contract = choices.chance(10);
    Input input = generate(kind, choices, options);
    ValueSource values(choices, {});
    make_touching(input, values);
    const ExactVerdict v = exact.judge(input);
    if (v.contract != Contract::in || !v.decided || std::isnan(v.margin)) return;
    ++judged;
    touching += std::fabs(v.margin) <= kRounding;
    exactly += v.margin == 0;
    RC_TAG(v.margin == 0 ? "exactly touching" : std::fabs(v.margin) <= kRounding ? "touching" : "overlapping");
    if (v.margin < -kRounding) {
      RC_FAIL("apart by " + format_double(-v.margin) + " of the scale after touch: " + input_to_json(input).dump());
    }
    if (touching_only && v.margin > kRounding) {
      RC_FAIL("overlapping by " + format_double(v.margin) + " of the scale after touch: " + input_to_json(input).dump());
    }
  });
  EXPECT_TRUE(passed) << property;
  std::cout << property << ": " << judged << " judged in contract, " << touching << " touching, " << exactly
            << " exactly" << std::endl;
  EXPECT_GT(touching, judged / 10) << property << ": the constructions rarely touch";
  EXPECT_GT(exactly, 0) << property << ": never touching exactly";
}

INSTANTIATE_TEST_SUITE_P(EveryQuery, Touch, ::testing::ValuesIn(kAllQueryKinds),
                         [](const auto& p) { return std::string(name(p.param)); });

// Inputs a case file may hold with nothing to move: a k-DOP of no points, a mesh of no vertices,
// a broadphase of no frames. make_touching leaves them as they are (and does not crash on them).
TEST(TouchNothing, AnInputWithNothingToTouchIsLeftAsItIs) {
  int kdops = 0, meshes = 0, broadphases = 0;
  const bool passed = check_property_with_choices("an input with nothing to touch is left as it is", 300, [&](Choices& choices) {
    GenerateOptions options;
    options.mesh_folder = fcl_mesh_folder() / "absent";  // procedural meshes: small and quick
    const QueryKind kinds[] = {QueryKind::kdop_kdop, QueryKind::broadphase, QueryKind::mesh_mesh};
    Input input = generate(kinds[choices.draw(3)], choices, options);
    if (auto* k = std::get_if<KdopKdopInput>(&input)) {
      (choices.chance(50) ? k->a : k->b).clear();
      ++kdops;
    } else if (auto* b = std::get_if<BroadphaseInput>(&input)) {
      b->frames.clear();
      ++broadphases;
    } else {
      MeshPair& m = std::get<MeshMeshInput>(input).meshes;
      (choices.chance(50) ? m.a : m.b) = triangles_mesh(Mesh{});
      ++meshes;
    }
    const Input before = input;
    ValueSource values(choices, {});
    make_touching(input, values);
    RC_ASSERT(input == before);
  });
  EXPECT_TRUE(passed);
  EXPECT_GT(kdops, 0);
  EXPECT_GT(meshes, 0);
  EXPECT_GT(broadphases, 0);
}

// A broadphase whose frames never hold two boxes (one slot, or boxes handed over frame to frame,
// as a fuzz record's masks may have them): make_touching gives a frame a second box, face to
// face with one it has.
TEST(TouchNothing, ABroadphaseOfOneBoxAtATimeGetsASecondBoxTouchingIt) {
  const exact::ExactRationalReference exact;
  int one_slot = 0, handed_over = 0;
  const bool passed = check_property_with_choices("a broadphase of one box at a time gets a touching second", 300, [&](Choices& choices) {
    auto in = std::get<BroadphaseInput>(generate(QueryKind::broadphase, choices, {}));
    if (choices.chance(50)) {
      for (auto& frame : in.frames) frame.resize(1);
      ++one_slot;
    } else {  // frame f holds slot f's box alone, if any: some frames hold none
      for (std::size_t f = 0; f < in.frames.size(); ++f) {
        for (std::size_t i = 0; i < in.frames[f].size(); ++i) {
          if (i != f) in.frames[f][i].reset();
        }
      }
      ++handed_over;
    }
    Input input = in;
    ValueSource values(choices, {});
    make_touching(input, values);
    const auto& touched = std::get<BroadphaseInput>(input);
    RC_ASSERT(std::ranges::any_of(touched.frames, [](const auto& frame) {
      return std::ranges::count_if(frame, [](const auto& box) { return box.has_value(); }) >= 2;
    }));
    const ExactVerdict v = exact.judge(input);
    if (v.contract != Contract::in || !v.decided || std::isnan(v.margin)) return;
    RC_ASSERT(std::fabs(v.margin) <= kRounding);
  });
  EXPECT_TRUE(passed);
  EXPECT_GT(one_slot, 0);
  EXPECT_GT(handed_over, 0);
}

}  // namespace
}  // namespace cc::test
