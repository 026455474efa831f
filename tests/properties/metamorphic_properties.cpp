// Metamorphic relations, no oracle needed where they are exact in floating point: swapping the
// two shapes, permuting the axes, flipping the sign of an axis and scaling by a power of two give
// the library's answer bit for bit (ray parameters included), and so do the reorderings of what
// the generators keep in order: a k-DOP's points, a scene's objects and a maze's walls (pairs
// renamed), a wall's ends, a mesh's faces (pairs renamed; the leaf tests see the same
// triangles). Where a relation does not apply
// (no second shape; a k-DOP direction set not closed under it: 16 under both, 24 under flips)
// it is skipped. Scaling is checked on inputs whose values lie in [2^-250, 2^250] (others flushed
// to 0), where no intermediate result of the library underflows or overflows.
//
// Six relations hold only as "equal, or another right answer", and the property checks that
// much, so a real asymmetry still fails it:
//  - reordering a triangle's vertices changes which edges the tests compute and so their
//    rounding (a tri_tri 9 ulps apart is a hit one way, a miss the other): the answers must be
//    equal, or both right within the library's band by the exact reference (a wall's ends, the
//    same relation for disc_walls, are exact);
//  - permuting the axes, for sphere_sphere, obb_obb, tri_tri and the mesh queries (whose leaf
//    test is tri_tri and whose OBB trees test their nodes with test_obb_obb): those tests sum three
//    terms left to right (plain floating-point arithmetic), and a permutation changes that order
//    and so the rounding, within the certified bound: equal, or both right within the band;
//  - exchanging x and y, or a mirror, for disc_walls: the disc tests take a wall's ends in
//    lexicographic order (so that swapping the ends is exact, and it is checked bit for bit), and
//    these may reverse it, and with it the end the rounded differences start from: equal, or both
//    right within the band;
//  - every relation but exchanging the triangles, for tri_tri_intersection: its rounded corners
//    change with the order of the axes and the vertices (both answers must be right, corners
//    within their tolerance by the exact reference); exchanging the triangles is exact;
//  - every relation, for the distance kinds: the witnesses are exchanged with the shapes and
//    follow the axes, the scale and the vertices' order only within their bounds (both answers
//    must be right by the exact reference);
//  - a first hit under reordered faces may be another pair: the same hit, and a pair of all
//    the pairs of the reordered meshes;
//  - the closest hit of a ray under reordered faces: the same hit and t, and the face renamed,
//    or another face hit at that same t (ties go to the smallest index).
// Reordering copies a mesh and builds its hierarchy again, so meshes of more than 512 faces in
// all (FCL's env.obj) are left out of those relations.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>

#include "collide/ray_mesh.h"
#include "harness/judging/evaluate.h"
#include "harness/formats/input_json.h"
#include "harness/model/library.h"
#include "harness/judging/metamorphic.h"
#include "oracle/exact/exact_reference.h"
#include "case_budget.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;

struct Case {
  QueryKind kind;
  Relation relation;
};

class Metamorphic : public ::testing::TestWithParam<Case> {};

std::size_t faces_of(const Input& input) {
  if (const MeshPair* m = meshes_of(input)) return m->a.mesh->size() + m->b.mesh->size();
  if (const auto* ray = std::get_if<RayMeshInput>(&input)) return ray->mesh.mesh->size();
  return 0;
}

// Whether the library is right on the input, or within its band, by the exact reference.
bool library_right(const Input& input, const exact::ExactRationalReference& exact) {
  return evaluate(input, exact, nullptr).verdict.parties[0].standing != Standing::wrong;
}

// The relations that hold as "equal, or another right answer" (see the top): whether `after`,
// the answer to the transformed input, is such another right answer where `before` (the
// original's, mapped) is not equal to it.
bool another_right_answer(const Input& input, const Input& transformed, const Answer& before, const Answer& after,
                          Relation relation, const exact::ExactRationalReference& exact) {
  const QueryKind kind = kind_of(input);
  const bool sums_in_order = kind == QueryKind::sphere_sphere || kind == QueryKind::obb_obb || kind == QueryKind::tri_tri ||
                             kind == QueryKind::mesh_mesh || kind == QueryKind::mesh_mesh_first;
  // A wall's ends are taken in lexicographic order, so swapping them is exact; a mirror or
  // exchanging x and y may reverse that order, and the end the test measures from.
  const bool ends_in_order = kind == QueryKind::disc_walls;
  // Rounded corners follow the axes' order and signs (and the scale) only up to their bound, and
  // the answer's corners are not mapped: both answers must be right by the exact reference.
  if (judged_of(kind) == Judged::corners && relation != Relation::swap_shapes) {
    return library_right(input, exact) && library_right(transformed, exact);
  }
  // A distance's witnesses are swapped with the shapes, and follow the axes, the scale and the
  // vertices' order only up to their bounds: both answers must be right by the exact reference.
  if (judged_of(kind) == Judged::distance) return library_right(input, exact) && library_right(transformed, exact);
  if ((relation == Relation::permute_vertices && !ends_in_order) ||
      ((relation == Relation::permute_axes || relation == Relation::flip_axis) && ends_in_order) ||
      (relation == Relation::permute_axes && sums_in_order)) {
    return library_right(input, exact) && library_right(transformed, exact);
  }
  if (relation != Relation::permute_faces || before.hit != after.hit) return false;
  if (const auto* first = std::get_if<MeshMeshFirstInput>(&transformed)) {
    const Answer all = ask_library(MeshMeshInput{first->meshes});
    return after.pairs.size() == 1 && std::binary_search(all.pairs.begin(), all.pairs.end(), after.pairs[0]);
  }
  if (const auto* ray = std::get_if<RayMeshInput>(&transformed)) {
    if (after.params != before.params || after.pairs.size() != 1) return false;
    const Triangle t = ray->mesh.mesh->triangle(after.pairs[0].first);
    const Mesh face{{t.v[0], t.v[1], t.v[2]}, {{0, 1, 2}}};
    const RayMeshHit alone = ray_mesh_brute_force(face, ray->ray);
    return alone.hit && alone.t == after.params[0];
  }
  return false;
}

TEST_P(Metamorphic, TheAnswerIsUnchanged) {
  const QueryKind kind = GetParam().kind;
  const Relation relation = GetParam().relation;  // not a structured binding: the lambda below captures it
  const exact::ExactRationalReference exact;
  const std::string property = std::string(name(kind)) + ": " + std::string(to_string(relation));
  Met met;
  int applied = 0;
  // Reordering a mesh builds its two hierarchies again: fewer cases than the other relations.
  const bool reorders = relation == Relation::permute_vertices || relation == Relation::permute_faces;
  const int cases = case_budget(kind, 1000, reorders ? 60 : 200);
  const bool passed = check_property(property, kind, 0, cases, met, [&](const Input& generated) {
    const Input input = relation == Relation::scale ? flush_extremes(generated) : generated;
    met.count(features_of(input, exact.judge(input)));
    int parameter = 0;
    switch (relation) {
      case Relation::permute_axes: parameter = *rc::gen::inRange(1, 6); break;
      case Relation::flip_axis: parameter = *rc::gen::inRange(0, 3); break;
      case Relation::scale: parameter = *rc::gen::element(-8, -3, -1, 1, 2, 7); break;
      case Relation::swap_shapes: break;
      case Relation::permute_vertices: parameter = *rc::gen::inRange(1, 36); break;
      default: parameter = *rc::gen::inRange(1, 1 << 30); break;
    }
    if (reorders && faces_of(input) > 512) return;
    const auto transformed = transform(input, relation, parameter);
    if (!transformed) return;
    ++applied;
    const Answer before = mapped_answer(ask_library(input), input, relation, parameter), after = ask_library(*transformed);
    if (!(before == after) && !another_right_answer(input, *transformed, before, after, relation, exact)) {
      RC_FAIL("the answer changed (" + std::to_string(before.hit) + " -> " + std::to_string(after.hit) +
              ") under parameter " + std::to_string(parameter) + "\n  inputs: " + input_to_json(input).dump());
    }
  });
  EXPECT_TRUE(passed) << property;
  EXPECT_GT(applied, cases / 10) << property << ": the relation hardly ever applied";
  expect_met_the_boundary(property, kind, met);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (QueryKind kind : kAllQueryKinds) {
    for (Relation r : kAllRelations) {
      if (relation_applies(kind, r)) cases.push_back({kind, r});
    }
  }
  return cases;
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string r(to_string(info.param.relation));
  for (char& c : r) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return std::string(name(info.param.kind)) + "_" + r;
}

INSTANTIATE_TEST_SUITE_P(EveryQueryAndRelation, Metamorphic, ::testing::ValuesIn(all_cases()), case_name);

}  // namespace
}  // namespace cc::test
