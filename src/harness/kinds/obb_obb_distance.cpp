// The obb_obb_distance kind: the collision kind's pairs of boxes (obb_obb.cpp) and boxes at a
// drawn signed gap against a face, asked for their signed distance. The library's call, and what
// its cases are.
#include "harness/kinds/obb_obb_distance.h"

#include <cmath>

#include "collide/obb_distance.h"
#include "collide/obb_distance_bound.h"
#include "collide/record_sink.h"
#include "harness/generation/gaps.h"
#include "harness/generation/shapes.h"
#include "harness/judging/configurations.h"
#include "harness/kinds/obb_obb.h"
#include "harness/kinds/separation_answer.h"

namespace cc::harness {
namespace {

using Collision = Query<ObbObbInput>;

// b against one of a's faces: along its outward normal at a's half extent plus b's reach on it
// plus a drawn gap of the larger box's size, laterally anywhere over the face and a little past it.
void at_a_gap(ObbObbDistanceInput& in, ValueSource& v) {
  Choices& c = v.choices();
  const int k = static_cast<int>(c.draw(3));
  const Vec3 n = (c.chance(50) ? 1.0 : -1.0) * in.a.axes.col[k];
  Vec3 lateral;
  for (int j = 0; j < 3; ++j) {
    if (j != k) lateral[j] = in.a.half[j] * (static_cast<double>(c.draw(41)) / 16 - 1.25);
  }
  const double size = std::max(max_abs(in.a.half), max_abs(in.b.half));
  const double gap = draw_gap(c) * size;
  in.b.center = in.a.center + in.a.axes * lateral + (in.a.half[k] + reach_along(in.b, n) + gap) * n;
}

constexpr BoundTerm kBoundTerms[] = {{"distance_obb_obb", "signed distance", "total"},
                                     {"distance_obb_obb", "witness", "total"}};

}  // namespace

Answer Query<ObbObbDistanceInput>::ask(const ObbObbDistanceInput& in) {
  return separation_answer(distance_obb_obb(in.a, in.b));
}

ObbObbDistanceInput Query<ObbObbDistanceInput>::generate(ValueSource& v, const GenerateOptions& options) {
  const ObbObbInput pair = Collision::generate(v, options);
  ObbObbDistanceInput in{pair.a, pair.b};
  if (!options.out_of_contract && v.choices().chance(40)) {
    if (v.choices().chance(40)) in.b.axes = in.a.axes;  // parallel faces and edges
    at_a_gap(in, v);
  }
  return in;
}

void Query<ObbObbDistanceInput>::touch(ObbObbDistanceInput& in, ValueSource& v) {
  ObbObbInput collision{in.a, in.b};
  Collision::touch(collision, v);
  in.b = collision.b;
}

Features Query<ObbObbDistanceInput>::features(const ObbObbDistanceInput& in) {
  return Collision::features(ObbObbInput{in.a, in.b});
}

std::span<const std::string_view> Query<ObbObbDistanceInput>::configurations() { return Collision::configurations(); }

void Query<ObbObbDistanceInput>::recognise(const ObbObbDistanceInput& in, Configurations& found) {
  Collision::recognise(ObbObbInput{in.a, in.b}, found);
}

std::span<const BoundTerm> Query<ObbObbDistanceInput>::bound_terms() { return kBoundTerms; }

void Query<ObbObbDistanceInput>::probe(const ObbObbDistanceInput& in, std::vector<bounds::Records>& records) {
  distance_obb_obb(in.a, in.b, bounds::next_call(records));
}

}  // namespace cc::harness
