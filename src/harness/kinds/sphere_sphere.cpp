// Generator for sphere_sphere: balls touching by construction (centres apart by a Pythagorean
// quadruple times a scale, radii summing exactly to its length), a few ULPs from touching,
// concentric, and points (radius 0); out of contract, a negative radius on either. The scale is
// a power of two (every square exact too) or a generic double whose squares round, either way
// of each other, while the offset, the reach and the radii stay exact.
#include "harness/kinds/sphere_sphere.h"

#include <cmath>

#include "collide/record_sink.h"
#include "collide/sphere_bound.h"
#include "harness/generation/regimes.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

struct Quadruple {
  int a, b, c, d;  // a^2 + b^2 + c^2 = d^2
};
constexpr Quadruple kQuadruples[] = {{0, 0, 1, 1}, {0, 3, 4, 5}, {1, 2, 2, 3},  {2, 3, 6, 7},
                                     {1, 4, 8, 9}, {2, 6, 9, 11}, {0, 5, 12, 13}, {4, 4, 7, 9}};

Sphere draw_sphere(ValueSource& v, const GenerateOptions& options) {
  Sphere s{v.point(), v.length()};
  if (options.out_of_contract && v.choices().chance(10)) s.radius = -s.radius - 1;
  return s;
}

// Two balls at an exact margin in the regimes of test_sphere_sphere's bound: far from the origin
// compared with their size, radii up to 2^40 apart, points; b slid from a's centre along any
// direction.
SphereSphereInput balls_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  const Vec3 offset = draw_far_offset(v, size);
  const Sphere a{v.point() + offset, c.chance(15) ? 0.0 : size};
  double rb = 0.0;
  if (!c.chance(15)) {
    const int exponent = v.small_int(40);
    rb = std::ldexp(draw_size(v), exponent) * (c.chance(50) ? 1.0 : size);
  }
  const Vec3 w = draw_direction(v);
  const double length = std::sqrt(dot(w, w));
  const auto placed = [&a, &w, rb](double s) { return SphereSphereInput{a, {a.center + s * w, rb}}; };
  const double contact = (a.radius + rb) / length;
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, 2 * contact + 1 / length,
                            draw_margin_target(c), options, contact);
  return placed(s);
}

constexpr std::string_view kConfigurations[] = {"touching", "just apart",  "just overlapping",   "point",
                                                "radii far apart", "concentric", "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {{"test_sphere_sphere", "squares", "distance"},
                                     {"test_sphere_sphere", "squares", "reach"},
                                     {"test_sphere_sphere", "squares", "total"}};

}  // namespace

Answer Query<SphereSphereInput>::ask(const SphereSphereInput& in) { return Answer::of(test_sphere_sphere(in.a, in.b)); }

SphereSphereInput Query<SphereSphereInput>::generate(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return balls_at_the_bound(v, options);
  SphereSphereInput in;
  in.a = draw_sphere(v, options);
  const auto mode = v.choices().draw(4);
  switch (mode) {
    case 0: in.b = draw_sphere(v, options); break;
    case 1:
    case 2: {  // touching by construction (case 2: then moved a few ULPs)
      const Quadruple q = kQuadruples[v.choices().draw(std::size(kQuadruples))];
      Vec3 offset{static_cast<double>(q.a), static_cast<double>(q.b), static_cast<double>(q.c)};
      for (int i = 2; i > 0; --i) std::swap(offset[i], offset[static_cast<int>(v.choices().draw(i + 1))]);
      for (int k = 0; k < 3; ++k) offset[k] *= v.choices().chance(50) ? -1 : 1;
      double scale = std::ldexp(1.0, v.small_int(8));
      if (v.choices().chance(50)) {
        // A generic scale of 46 bits: times the quadruple's numbers (4 bits) and the centres'
        // grid (6 bits) it stays exact, its squares do not.
        scale *= 1 + static_cast<double>(v.choices().draw(std::uint64_t{1} << 45)) * 0x1p-45;
        in.a.center = scale * Vec3{static_cast<double>(v.small_int(32)), static_cast<double>(v.small_int(32)),
                                   static_cast<double>(v.small_int(32))};
      }
      const double reach = scale * q.d;
      in.a.radius = reach * static_cast<double>(v.choices().draw(5)) / 4;  // 0, 1/4, ..., 1 of the reach
      if (v.choices().chance(50)) {
        // A generic radius in [reach/2, reach]: the other, reach minus it, is exact (Sterbenz).
        in.a.radius = reach * (0.5 + static_cast<double>(v.choices().draw(std::uint64_t{1} << 40)) * 0x1p-41);
      }
      in.b.center = in.a.center + scale * offset;
      in.b.radius = reach - in.a.radius;
      if (mode == 2) in.b.radius = std::fabs(v.nudge(in.b.radius));
      break;
    }
    default:  // concentric, or the same point
      in.b = {in.a.center, v.choices().chance(50) ? v.length() : in.a.radius};
  }
  // Out of contract also where the balls touch or nest by construction: a negative radius on
  // either ball, where a test that checks the sign of only one radius answers true.
  if (options.out_of_contract && v.choices().chance(30)) {
    Sphere& s = v.choices().chance(50) ? in.a : in.b;
    s.radius = s.radius > 0 ? -s.radius : -1.0;
  }
  return in;
}

void Query<SphereSphereInput>::touch(SphereSphereInput& in, ValueSource& v) {
  Choices& c = v.choices();
  Vec3 offset;
  offset[static_cast<int>(c.draw(3))] = (c.chance(50) ? -1.0 : 1.0) * (in.a.radius + in.b.radius);
  in.b.center = in.a.center + offset;
}

Features Query<SphereSphereInput>::features(const SphereSphereInput& in) {
  return {false, false, in.a.radius == 0 || in.b.radius == 0};
}

std::span<const std::string_view> Query<SphereSphereInput>::configurations() { return kConfigurations; }

void Query<SphereSphereInput>::recognise(const SphereSphereInput& in, Configurations& found) {
  found.margins();
  found.add("point", in.a.radius == 0 || in.b.radius == 0);
  const double lo = std::min(in.a.radius, in.b.radius), hi = std::max(in.a.radius, in.b.radius);
  found.add("radii far apart", lo > 0 && hi >= kFar * lo);
  found.add("concentric", in.a.center == in.b.center);
  found.far(std::max(max_abs(in.a.center), max_abs(in.b.center)), in.a.radius + in.b.radius);
}

std::span<const BoundTerm> Query<SphereSphereInput>::bound_terms() { return kBoundTerms; }

void Query<SphereSphereInput>::probe(const SphereSphereInput& in, std::vector<bounds::Records>& records) {
  test_sphere_sphere(in.a, in.b, bounds::next_call(records));
}

}  // namespace cc::harness
