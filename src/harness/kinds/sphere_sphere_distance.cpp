// The sphere_sphere_distance kind: sphere_sphere's cases (touching by construction, a few ULPs
// from it, concentric, points, radii far apart, far from the origin), and balls placed at a drawn
// signed gap along a drawn direction (0, 2^0 down to 2^-60 of their size either way), one deep in
// the other, or nested; scaled by 2^-300 to 2^300. The library's call, and what its cases are.
#include "harness/kinds/sphere_sphere_distance.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "collide/record_sink.h"
#include "collide/sphere_distance.h"
#include "collide/sphere_distance_bound.h"
#include "harness/generation/gaps.h"
#include "harness/generation/regimes.h"
#include "harness/judging/configurations.h"
#include "harness/kinds/sphere_sphere.h"
#include "harness/kinds/separation_answer.h"

namespace cc::harness {
namespace {

// Two balls of drawn radii whose surfaces are a drawn gap apart along a drawn direction (the
// centres' offset rounded, so the gap holds within a few ULPs of the reach), or b inside a.
SphereSphereDistanceInput at_a_gap(ValueSource& v) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  const Sphere a{v.point() + draw_far_offset(v, size), c.chance(15) ? 0.0 : size};
  const double rb = c.chance(15) ? 0.0 : std::ldexp(size, v.small_int(40));
  const Vec3 w = draw_direction(v);  // never zero
  const double length = std::sqrt(dot(w, w));
  double reach = a.radius + rb + draw_gap(c) * size;
  if (c.chance(20)) reach = std::fabs(a.radius - rb) * static_cast<double>(c.draw(5)) / 4;  // nested, inner ones touching
  return {a, {a.center + (std::max(reach, 0.0) / length) * w, rb}};
}

constexpr std::string_view kConfigurations[] = {"touching",   "just apart", "just overlapping", "apart",
                                                "nested",     "concentric", "point",            "radii far apart",
                                                "tiny",       "huge",       "far from the origin"};

// The bounds of the answer, term by term: the rounding alone (balls; boxes with exactly
// orthonormal axes) and the whole bound, of the distance and of the witnesses.
constexpr BoundTerm kBoundTerms[] = {{"distance_sphere_sphere", "signed distance", "rounding"},
                                     {"distance_sphere_sphere", "signed distance", "total"},
                                     {"distance_sphere_sphere", "witness", "rounding"},
                                     {"distance_sphere_sphere", "witness", "total"}};

}  // namespace

Answer Query<SphereSphereDistanceInput>::ask(const SphereSphereDistanceInput& in) {
  return separation_answer(distance_sphere_sphere(in.a, in.b));
}

SphereSphereDistanceInput Query<SphereSphereDistanceInput>::generate(ValueSource& v, const GenerateOptions& options) {
  // Out of contract (NaN, infinities, negative radii), the two-ball generator's cases only.
  SphereSphereDistanceInput in;
  if (options.out_of_contract || v.choices().chance(40)) {
    const SphereSphereInput pair = Query<SphereSphereInput>::generate(v, options);
    in = {pair.a, pair.b};
  } else {
    in = at_a_gap(v);
  }
  if (!options.out_of_contract && v.choices().chance(30)) {
    Sphere &a = in.a, &b = in.b;
    scale_by_a_power_of_two(v.choices(), {&a.center.x, &a.center.y, &a.center.z, &a.radius, &b.center.x, &b.center.y,
                                          &b.center.z, &b.radius});
  }
  if (v.choices().chance(50)) std::swap(in.a, in.b);
  return in;
}

void Query<SphereSphereDistanceInput>::touch(SphereSphereDistanceInput& in, ValueSource& v) {
  SphereSphereInput pair{in.a, in.b};
  Query<SphereSphereInput>::touch(pair, v);
  in = {pair.a, pair.b};
}

Features Query<SphereSphereDistanceInput>::features(const SphereSphereDistanceInput& in) {
  return Query<SphereSphereInput>::features({in.a, in.b});
}

std::span<const std::string_view> Query<SphereSphereDistanceInput>::configurations() { return kConfigurations; }

void Query<SphereSphereDistanceInput>::recognise(const SphereSphereDistanceInput& in, Configurations& found) {
  found.margins();
  const ExactVerdict& exact = found.exact();
  const bool decided = exact.contract == Contract::in && exact.decided;
  found.add("apart", decided && exact.margin < -kJust);
  const double lo = std::min(in.a.radius, in.b.radius), hi = std::max(in.a.radius, in.b.radius);
  const Vec3 d = in.b.center - in.a.center;
  found.add("nested", decided && lo > 0 && std::sqrt(dot(d, d)) + lo < hi);
  found.add("concentric", in.a.center == in.b.center);
  found.add("point", in.a.radius == 0 || in.b.radius == 0);
  found.add("radii far apart", lo > 0 && hi >= kFar * lo);
  const double largest = std::max({max_abs(in.a.center), max_abs(in.b.center), hi});
  found.add("tiny", largest > 0 && largest < 0x1p-200);
  found.add("huge", largest > 0x1p200);
  found.far(std::max(max_abs(in.a.center), max_abs(in.b.center)), in.a.radius + in.b.radius);
}

std::span<const BoundTerm> Query<SphereSphereDistanceInput>::bound_terms() { return kBoundTerms; }

void Query<SphereSphereDistanceInput>::probe(const SphereSphereDistanceInput& in, std::vector<bounds::Records>& records) {
  distance_sphere_sphere(in.a, in.b, bounds::next_call(records));
}

}  // namespace cc::harness
