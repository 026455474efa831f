// The sphere_obb_distance kind: a ball against a box, the ball's centre in a drawn region of the
// box's frame (nearest a face, an edge or a corner, inside or on the boundary), its surface at a
// drawn signed gap (0, 2^0 down to 2^-60 of the size either way); boxes with aspect ratios up to
// 2^40, flat ones, axes at the orthonormality tolerance, far from the origin; exactly touching a
// face, an edge or a corner on a grid (Pythagorean offsets), or a few ULPs off; scaled by 2^-300
// to 2^300. The library's call, and what its cases are.
#include "harness/kinds/sphere_obb_distance.h"

#include <algorithm>
#include <cmath>

#include "collide/record_sink.h"
#include "collide/sphere_distance.h"
#include "collide/sphere_distance_bound.h"
#include "harness/generation/gaps.h"
#include "harness/generation/regimes.h"
#include "harness/generation/rotation.h"
#include "harness/generation/shapes.h"
#include "harness/judging/configurations.h"
#include "harness/kinds/separation_answer.h"

namespace cc::harness {
namespace {

// The centre's coordinates in the box's frame and, outside, the direction it is pushed out along.
struct Region {
  Vec3 local, out;
};

// Each coordinate held at +half or -half (then pushed out along it, by a drawn positive weight)
// or free inside [-half, half] (by 1/16 steps); at least one held when `outside`.
Region draw_region(Choices& c, const Vec3& half, bool outside) {
  Region r;
  int held = 0;
  for (int k = 0; k < 3; ++k) {
    const auto side = c.draw(3);
    if (side == 0) {
      r.local[k] = half[k] * (static_cast<double>(c.draw(33)) / 16 - 1);
    } else {
      r.local[k] = side == 1 ? half[k] : -half[k];
      r.out[k] = (side == 1 ? 1.0 : -1.0) * static_cast<double>(1 + c.draw(4));
      ++held;
    }
  }
  if (outside && held == 0) {
    const int k = static_cast<int>(c.draw(3));
    r.local[k] = half[k], r.out[k] = 1;
  }
  return r;
}

// A box in the regimes of the box tests (aspect ratios, flat, axes at the tolerance, far away) and
// a ball whose surface is a drawn gap from it, its centre outside in a drawn region, or inside.
SphereObbDistanceInput near_the_box(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  SphereObbDistanceInput in;
  in.box.center = v.point() + draw_far_offset(v, size);
  in.box.half = draw_aspect_extents(v, size);
  in.box.axes = c.chance(25) ? Mat3::identity() : draw_rotation(v);
  if (c.chance(30)) in.box.axes = perturb_to_tolerance(v, in.box.axes);
  if (options.out_of_contract && c.chance(20)) in.box = draw_obb(v, options);
  in.ball.radius = c.chance(15) ? 0.0 : std::ldexp(size, v.small_int(20));
  const bool inside = c.chance(25);
  Region r = draw_region(c, in.box.half, !inside);
  if (inside) {
    // Inside, on a face (held) or below it by the gap; the radius any.
    for (int k = 0; k < 3; ++k) {
      if (r.out[k] != 0) r.local[k] -= std::copysign(std::min(std::fabs(draw_gap(c)) * size, in.box.half[k]), r.out[k]);
    }
  } else {
    const double distance = std::max(in.ball.radius + draw_gap(c) * size, 0.0);
    const double length = std::sqrt(dot(r.out, r.out));
    r.local = r.local + (distance / length) * r.out;
  }
  in.ball.center = in.box.center + in.box.axes * r.local;
  return in;
}

struct Quadruple {
  int a, b, c, d;  // a^2 + b^2 + c^2 = d^2
};
constexpr Quadruple kQuadruples[] = {{0, 0, 1, 1}, {0, 3, 4, 5}, {1, 2, 2, 3}, {2, 3, 6, 7}, {0, 5, 12, 13}, {2, 6, 9, 11}};

// An axis-aligned box on a grid of 2^e and a ball touching it exactly at a face, an edge or a
// corner (a Pythagorean offset from the held coordinates), or with its radius a few ULPs off.
SphereObbDistanceInput touching_on_a_grid(ValueSource& v) {
  Choices& c = v.choices();
  const double unit = std::ldexp(1.0, v.small_int(40));
  const auto grid = [&v, unit](int limit) { return unit * v.small_int(limit); };
  SphereObbDistanceInput in;
  in.box = {{grid(8), grid(8), grid(8)}, {unit * static_cast<double>(c.draw(5)), unit * static_cast<double>(c.draw(5)), unit * static_cast<double>(c.draw(5))}, Mat3::identity()};
  const Quadruple q = kQuadruples[c.draw(std::size(kQuadruples))];
  const double offset[3] = {static_cast<double>(q.a), static_cast<double>(q.b), static_cast<double>(q.c)};
  Vec3 local;
  for (int k = 0; k < 3; ++k) {
    const double h = in.box.half[k];
    const double sign = c.chance(50) ? 1.0 : -1.0;
    local[k] = offset[k] == 0 ? std::clamp(grid(4), -h, h) : sign * (h + unit * offset[k]);
  }
  in.ball = {in.box.center + local, unit * q.d};
  if (c.chance(40)) in.ball.radius = v.nudge(in.ball.radius);
  return in;
}

constexpr std::string_view kConfigurations[] = {
    "touching",   "just apart", "just overlapping", "apart",   "centre inside", "nearest a face", "nearest an edge",
    "nearest a corner", "point ball", "flat box", "segment box", "point box", "long box", "tiny", "huge",
    "far from the origin"};

// The centre's coordinates in the box's frame (rounded), for telling the configurations apart.
Vec3 local_centre(const SphereObbDistanceInput& in) {
  const Vec3 d = in.ball.center - in.box.center;
  return {dot(in.box.axes.col[0], d), dot(in.box.axes.col[1], d), dot(in.box.axes.col[2], d)};
}

// The bounds of the answer, term by term: the rounding alone (balls; boxes with exactly
// orthonormal axes) and the whole bound, of the distance and of the witnesses.
constexpr BoundTerm kBoundTerms[] = {{"distance_sphere_obb", "signed distance", "rounding"},
                                     {"distance_sphere_obb", "signed distance", "total"},
                                     {"distance_sphere_obb", "witness", "rounding"},
                                     {"distance_sphere_obb", "witness", "total"}};

}  // namespace

Answer Query<SphereObbDistanceInput>::ask(const SphereObbDistanceInput& in) {
  return separation_answer(distance_sphere_obb(in.ball, in.box));
}

SphereObbDistanceInput Query<SphereObbDistanceInput>::generate(ValueSource& v, const GenerateOptions& options) {
  SphereObbDistanceInput in;
  if (!options.out_of_contract && v.choices().chance(30)) {
    in = touching_on_a_grid(v);
  } else {
    in = near_the_box(v, options);
  }
  if (options.out_of_contract && v.choices().chance(30)) {
    in.ball = {v.point(), v.choices().chance(50) ? -v.length() - 1 : v.length()};
  }
  if (!options.out_of_contract && v.choices().chance(30)) {
    Vec3 &c = in.ball.center, &b = in.box.center, &h = in.box.half;
    scale_by_a_power_of_two(v.choices(), {&c.x, &c.y, &c.z, &in.ball.radius, &b.x, &b.y, &b.z, &h.x, &h.y, &h.z});
  }
  return in;
}

void Query<SphereObbDistanceInput>::touch(SphereObbDistanceInput& in, ValueSource& v) {
  const int k = static_cast<int>(v.choices().draw(3));
  const double side = v.choices().chance(50) ? 1.0 : -1.0;
  in.ball.center = in.box.center + (side * (in.box.half[k] + in.ball.radius)) * in.box.axes.col[k];
}

Features Query<SphereObbDistanceInput>::features(const SphereObbDistanceInput& in) {
  const Vec3& h = in.box.half;
  return {false, false, in.ball.radius == 0 || h.x == 0 || h.y == 0 || h.z == 0};
}

std::span<const std::string_view> Query<SphereObbDistanceInput>::configurations() { return kConfigurations; }

void Query<SphereObbDistanceInput>::recognise(const SphereObbDistanceInput& in, Configurations& found) {
  found.margins();
  const ExactVerdict& exact = found.exact();
  found.add("apart", exact.contract == Contract::in && exact.decided && exact.margin < -kJust);
  const Vec3 q = local_centre(in);
  int beyond = 0;
  for (int k = 0; k < 3; ++k) beyond += std::fabs(q[k]) > in.box.half[k];
  found.add("centre inside", beyond == 0);
  found.add("nearest a face", beyond == 1);
  found.add("nearest an edge", beyond == 2);
  found.add("nearest a corner", beyond == 3);
  found.add("point ball", in.ball.radius == 0);
  found.boxes(in.box.half);
  const double size = std::max({in.box.half.x, in.box.half.y, in.box.half.z, in.ball.radius});
  const double largest = std::max({max_abs(in.ball.center), max_abs(in.box.center), size});
  found.add("tiny", largest > 0 && largest < 0x1p-200);
  found.add("huge", largest > 0x1p200);
  found.far(std::max(max_abs(in.ball.center), max_abs(in.box.center)), size);
}

std::span<const BoundTerm> Query<SphereObbDistanceInput>::bound_terms() { return kBoundTerms; }

void Query<SphereObbDistanceInput>::probe(const SphereObbDistanceInput& in, std::vector<bounds::Records>& records) {
  distance_sphere_obb(in.ball, in.box, bounds::next_call(records));
}

}  // namespace cc::harness
