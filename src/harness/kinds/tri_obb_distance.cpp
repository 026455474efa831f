// The tri_obb_distance kind: the collision kind's triangles and boxes (tri_obb.cpp), asked for
// their signed distance. The library's call, and what its cases are.
#include "harness/kinds/tri_obb_distance.h"


#include "collide/record_sink.h"
#include "collide/triangle_box_distance.h"
#include "collide/triangle_box_distance_bound.h"
#include "harness/generation/generate.h"
#include "harness/generation/values.h"
#include "harness/judging/configurations.h"
#include "harness/kinds/separation_answer.h"
#include "harness/kinds/tri_obb.h"

namespace cc::harness {
namespace {

using Collision = Query<TriObbInput>;

constexpr BoundTerm kBoundTerms[] = {{"distance_triangle_obb", "signed distance", "total"},
                                     {"distance_triangle_obb", "witness", "total"}};

}  // namespace

Answer Query<TriObbDistanceInput>::ask(const TriObbDistanceInput& in) {
  return separation_answer(distance_triangle_obb(in.tri, in.box));
}

TriObbDistanceInput Query<TriObbDistanceInput>::generate(ValueSource& v, const GenerateOptions& options) {
  const TriObbInput pair = Collision::generate(v, options);
  return {pair.tri, pair.box};
}

void Query<TriObbDistanceInput>::touch(TriObbDistanceInput& in, ValueSource& v) {
  TriObbInput collision{in.tri, in.box};
  Collision::touch(collision, v);
  in.tri = collision.tri;
}

Features Query<TriObbDistanceInput>::features(const TriObbDistanceInput& in) {
  return Collision::features(TriObbInput{in.tri, in.box});
}

std::span<const std::string_view> Query<TriObbDistanceInput>::configurations() { return Collision::configurations(); }

void Query<TriObbDistanceInput>::recognise(const TriObbDistanceInput& in, Configurations& found) {
  Collision::recognise(TriObbInput{in.tri, in.box}, found);
}

std::span<const BoundTerm> Query<TriObbDistanceInput>::bound_terms() { return kBoundTerms; }

void Query<TriObbDistanceInput>::probe(const TriObbDistanceInput& in, std::vector<bounds::Records>& records) {
  distance_triangle_obb(in.tri, in.box, bounds::next_call(records));
}

}  // namespace cc::harness
