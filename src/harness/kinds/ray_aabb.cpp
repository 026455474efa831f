// Generator for ray_aabb: rays parallel to a slab with the origin on, inside or just outside
// it; rays aimed at a corner, an edge or a face (exactly, or up to rounding); rays starting
// inside; segments ending or starting on the boundary, with simple values or with generic ones
// where the slab parameter rounds either way of the segment's end; tmax = 0; empty parameter
// ranges; lines (tmin = -inf); zero directions.
#include "harness/kinds/ray_aabb.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "collide/ray_aabb_batch.h"
#include "collide/ray_slab_bound.h"
#include "collide/record_sink.h"
#include "harness/generation/regimes.h"
#include "harness/generation/shapes.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

// A direction component that makes the ray parallel to a slab: 0, -0, or subnormals whose
// reciprocal overflows (parallel by contract) or does not (not parallel).
double parallel_component(ValueSource& v) {
  switch (v.choices().draw(4)) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return (v.choices().chance(50) ? 1 : -1) * std::numeric_limits<double>::denorm_min();
    default: return (v.choices().chance(50) ? 1 : -1) * std::ldexp(1.0, -1023 - static_cast<int>(v.choices().draw(3)));
  }
}

// A simple direction: small integers and powers of two, so that o + t d is often exact.
Vec3 simple_direction(ValueSource& v) {
  Vec3 d;
  for (int k = 0; k < 3; ++k) d[k] = v.choices().chance(70) ? v.small_int(3) : std::ldexp(1.0, v.small_int(6));
  return d;
}

// A generic positive value with a significand of `bits` bits and an exponent in [-limit,
// limit]; the simplest is 1.
double generic_value(ValueSource& v, int bits, int limit) {
  const auto fraction = v.choices().draw(std::uint64_t{1} << (bits - 1));
  return std::ldexp(1 + std::ldexp(static_cast<double>(fraction), 1 - bits), v.small_int(limit));
}

// An odd integer below 2^26 (the product of two is exact); the simplest is 1.
double odd_factor(ValueSource& v) { return static_cast<double>(2 * v.choices().draw(std::uint64_t{1} << 25) + 1); }

// The value of the lowest set bit of x (finite, nonzero): x is an odd multiple of it.
double lowest_bit(double x) {
  int e = 0;
  const double m = std::frexp(std::fabs(x), &e);  // |x| = m 2^e, m in [1/2, 1)
  return std::ldexp(1.0, e - 53 + std::countr_zero(static_cast<std::uint64_t>(std::ldexp(m, 53))));
}

// A direction component d near 2^c for a segment of length t = A 2^a (A odd, below 2^26) from
// a face at f: d = B h 2^-a with B odd and below 2^26 and h a power of two on whose grid f lies
// (f = F h) with F below 2^52 or odd, so that t d = A B h and f -+ A B h are exact (F -+ A B
// is below 2^53, or even and below 2^54). The simplest is 1 for t = 1.
double exact_component(ValueSource& v, double f, int a, int c) {
  const double b = odd_factor(v);
  double h = std::ldexp(1.0, c + a - std::ilogb(b));
  if (f != 0) {
    int e = 0;
    std::frexp(f, &e);  // |f| < 2^e
    const double lowest = lowest_bit(f);
    h = std::clamp(h, std::min(std::ldexp(1.0, e - 52), lowest), lowest);
  }
  return std::ldexp(b * h, -a);
}

// A ray and a box at an exact margin in the regimes of intersect_ray_aabb's bound: boxes of
// aspect ratio up to 2^40 far from the origin, rays from up to 2^40 times the box's size away (or
// from very near), nearly parallel to a slab, with negative parameters (the box behind the origin
// on a line), and segments; the ray slid sideways until it grazes the box.
RayAabbInput ray_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  const Vec3 offset = draw_far_offset(v, size);
  const Vec3 center = v.point() + offset, half = draw_aspect_extents(v, size);
  RayAabbInput in;
  in.box = {center - half, center + half};
  Vec3 d = draw_direction(v);
  if (c.chance(30)) {  // nearly parallel to a slab
    const int k = static_cast<int>(c.draw(3));
    const double sign = c.chance(50) ? -1.0 : 1.0;
    d[k] = sign * std::ldexp(max_abs(d), -static_cast<int>(8 + c.draw(53)));
  }
  const double distance = std::ldexp(1.0, v.small_int(40)) * size / max_abs(d);  // the centre at t = distance
  const bool behind = c.chance(25);  // a line whose box lies at negative parameters
  const Vec3 origin = behind ? center + distance * d : center - distance * d;
  in.ray = {origin, d, behind ? -INFINITY : 0, INFINITY};
  if (!behind && c.chance(30)) {
    // A segment whose end is slid to the box's entry face: the slab parameter rounds either way.
    const auto ending = [&in](double t) {
      RayAabbInput out = in;
      out.ray.tmax = t;
      return out;
    };
    double entry = 0;  // in floating point: the largest near slab parameter
    for (int k = 0; k < 3; ++k) {
      if (d[k] != 0) entry = std::max(entry, ((d[k] > 0 ? in.box.lo[k] : in.box.hi[k]) - origin[k]) / d[k]);
    }
    const double t = place_at([&ending](double x) -> Input { return ending(x); }, distance, 0, draw_margin_target(c),
                              options, entry);
    return ending(t);
  }
  if (c.chance(20)) in.ray.tmax = distance * (c.chance(50) ? 1.0 : 0.5 + static_cast<double>(c.draw(1024)) / 512);
  // Sideways: across the direction, towards a face, an edge or any.
  Vec3 w = cross(d, Vec3{c.chance(34) ? 1.0 : 0.0, c.chance(50) ? 1.0 : 0.0, 1.0});
  if (c.chance(30) || !(max_abs(w) > 0)) w = draw_direction(v);
  const double shadow = (std::fabs(half.x * w.x) + std::fabs(half.y * w.y) + std::fabs(half.z * w.z)) / dot(w, w);
  const auto placed = [&in, &w](double s) {
    RayAabbInput out = in;
    out.ray.origin = in.ray.origin + s * w;
    return out;
  };
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, 2 * shadow + size / std::sqrt(dot(w, w)),
                            draw_margin_target(c), options, shadow);
  return placed(s);
}

// ray_aabb through the batched test: the case's box at place 3 of 11 (in a vector block of 8
// or 4) and at place 10 (in the scalar tail: 11 = 8 + 3 = 2 * 4 + 3), the other places holding
// boxes made from it (moved by its size, inverted, a point at a corner, NaN, unbounded), each
// answered by every kernel this processor runs. The answer is the hit they all give; a kernel or
// a place that differs from the scalar test on any box is a failure (an impl_bug).
Answer batched_ray(const RayAabbInput& in) {
  const Aabb& box = in.box;
  const Vec3 size = box.hi - box.lo;
  const Aabb fillers[9] = {{box.lo + Vec3{size.x, 0, 0}, box.hi + Vec3{size.x, 0, 0}},
                           {box.lo - Vec3{0, size.y, 0}, box.hi - Vec3{0, size.y, 0}},
                           {box.hi, box.lo},
                           {box.lo, box.lo},
                           {box.hi, box.hi},
                           {{box.lo.x, NAN, box.lo.z}, box.hi},
                           {box.lo, {box.hi.x, box.hi.y, INFINITY}},
                           {box.lo + Vec3{0, 0, size.z}, box.hi + Vec3{0, 0, size.z}},
                           {{-box.hi.x, box.lo.y, box.lo.z}, {-box.lo.x, box.hi.y, box.hi.z}}};
  constexpr std::size_t kInBlock = 3, kInTail = 10, kBoxes = 11;
  AabbSoa boxes;
  for (std::size_t i = 0, f = 0; i < kBoxes; ++i) boxes.push_back(i == kInBlock || i == kInTail ? box : fillers[f++]);
  std::vector<std::uint64_t> hits(hit_words(kBoxes));
  for (simd::Kernel kernel : simd::supported_kernels()) {
    test_ray_aabbs(in.ray, boxes, hits, kernel);
    for (std::size_t i = 0; i < kBoxes; ++i) {
      const bool scalar = intersect_ray_aabb(in.ray, boxes[i]).hit;
      if (hit_bit(hits, i) != scalar) {
        throw std::logic_error("the " + std::string(simd::to_string(kernel)) + " kernel says " +
                               (hit_bit(hits, i) ? "hit" : "miss") + " for box " + std::to_string(i) + " of " +
                               std::to_string(kBoxes) + (i == kInBlock || i == kInTail ? " (the case's)" : "") +
                               ", intersect_ray_aabb " + (scalar ? "hit" : "miss"));
      }
    }
  }
  return Answer::of(hit_bit(hits, kInBlock));
}

constexpr std::string_view kConfigurations[] = {
    "touching",  "just apart", "just overlapping", "parallel to a slab", "nearly parallel to a slab",
    "from far away", "negative parameters", "segment", "zero direction", "flat box", "point box", "long box",
    "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {{"intersect_ray_aabb", "slab parameter", "rounding"},
                                     {"intersect_ray_aabb", "slab parameter", "total"}};

}  // namespace

Answer Query<RayAabbInput>::ask(const RayAabbInput& in) {
  const RayHit h = intersect_ray_aabb(in.ray, in.box);
  if (!h.hit) return {};
  Answer a = Answer::of(true);
  a.params = {h.t_enter, h.t_exit};
  return a;
}

const std::vector<Party<RayAabbInput>>& Query<RayAabbInput>::library_parties() {
  static const std::vector<Party<RayAabbInput>> parties = {
      {"library.test_ray_aabbs", band, [](const RayAabbInput& in) { return answered(batched_ray(in)); }}};
  return parties;
}

RayAabbInput Query<RayAabbInput>::generate(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return ray_at_the_bound(v, options);
  RayAabbInput in;
  in.box = draw_aabb(v, options);
  Ray& r = in.ray;
  r.tmin = 0;
  r.tmax = INFINITY;
  switch (v.choices().draw(6)) {
    case 0:
      r.origin = v.point();
      r.dir = v.point();
      break;
    case 1: {  // parallel to slab k, origin on its boundary, inside, or a few ULPs outside
      const int k = static_cast<int>(v.choices().draw(3));
      const Vec3 target = draw_boundary_point(v, in.box);
      r.dir = simple_direction(v);
      const double t = std::ldexp(1.0, v.small_int(4));
      r.origin = target - t * r.dir;
      r.dir[k] = parallel_component(v);
      switch (v.choices().draw(3)) {
        case 0: r.origin[k] = v.choices().chance(50) ? in.box.lo[k] : in.box.hi[k]; break;
        case 1: r.origin[k] = 0.5 * (in.box.lo[k] + in.box.hi[k]); break;
        default: r.origin[k] = v.nudge(v.choices().chance(50) ? in.box.lo[k] : in.box.hi[k]);
      }
      break;
    }
    case 2: {  // aimed at a boundary point; a segment may end or start there
      const Vec3 target = draw_boundary_point(v, in.box);
      if (v.choices().chance(40)) {
        // Simple values make o + t d exact, so the segment ends on the boundary exactly and the
        // slab parameters are often exact too.
        r.dir = simple_direction(v);
        const double t = std::ldexp(1.0, v.small_int(4));
        r.origin = target - t * r.dir;
        if (v.choices().chance(40)) r.tmax = v.choices().chance(70) ? t : v.nudge(t);
        break;
      }
      // Generic values that keep the segment's end on the boundary exactly: on the axes where
      // the target lies on a face, t and the direction's component come from exact_component,
      // so that o = target - t d and t d are exact, and the slab parameter (f - o) (1/d)
      // computed in floating point rounds either way of t. The direction enters the box through
      // the target's faces where the segment ends there, and leaves through them where it
      // starts there. One case in five has generic directions of 53 bits instead: o + t d misses
      // the target by the rounding of o, inside or outside.
      const bool rounded = v.choices().chance(20);
      const auto end = v.choices().draw(3);  // 0: a ray, 1: a segment ending there, 2: starting there
      const double odd = odd_factor(v);
      const int a = v.small_int(4) - std::ilogb(odd);  // t = odd 2^a in [1, 2) 2^small_int
      const double t = std::ldexp(odd, a);
      for (int k = 0; k < 3; ++k) {
        const bool on_lo = target[k] == in.box.lo[k], on_hi = target[k] == in.box.hi[k];
        const bool negative = (on_lo || on_hi) && end != 0 ? (end == 1 ? on_hi : on_lo) : v.choices().chance(50);
        const double size = (on_lo || on_hi) && !rounded ? exact_component(v, target[k], a, v.small_int(8))
                                                         : generic_value(v, rounded ? 53 : 26, 8);
        r.dir[k] = negative ? -size : size;
      }
      r.origin = target - t * r.dir;
      if (end == 1) r.tmax = t;
      if (end == 2) r.tmin = t;
      break;
    }
    case 3:  // starting inside, or on the boundary
      r.origin = v.choices().chance(50) ? 0.5 * (in.box.lo + in.box.hi) : draw_boundary_point(v, in.box);
      r.dir = v.choices().chance(50) ? simple_direction(v) : v.point();
      break;
    case 4:  // special parameter ranges: a point (tmax = 0), tmin = tmax, empty, a line
      r.origin = v.choices().chance(50) ? draw_boundary_point(v, in.box) : v.point();
      r.dir = simple_direction(v);
      switch (v.choices().draw(4)) {
        case 0: r.tmax = 0; break;
        case 1: r.tmin = r.tmax = v.coordinate(); break;
        case 2: r.tmin = 1, r.tmax = v.choices().chance(50) ? 0.0 : std::nextafter(1.0, 0.0); break;
        default: r.tmin = -INFINITY;
      }
      break;
    default:  // zero direction: a point test
      r.origin = v.choices().chance(50) ? draw_boundary_point(v, in.box) : v.point();
      r.dir = {};
  }
  if (v.choices().chance(15)) r.tmax = std::fabs(v.coordinate());  // a segment
  if (v.choices().chance(10)) {
    // An extreme direction (the direction is not a coordinate: up to DBL_MAX), with t scaled back.
    const int k = v.small_int(1000);
    r.dir = {std::ldexp(r.dir.x, k), std::ldexp(r.dir.y, k), std::ldexp(r.dir.z, k)};
    r.tmin = std::ldexp(r.tmin, -k), r.tmax = std::ldexp(r.tmax, -k);
  }
  if (options.out_of_contract && v.choices().chance(15)) r.tmin = v.coordinate();
  return in;
}

void Query<RayAabbInput>::touch(RayAabbInput& in, ValueSource& v) {
  const Vec3 p = draw_boundary_point(v, in.box);
  if (in.ray.dir == Vec3{}) in.ray.dir = {1, 0, 0};
  const double t = std::ldexp(1.0, v.small_int(4));
  in.ray.origin = p - t * in.ray.dir;
  if (!(in.ray.tmin <= t)) in.ray.tmin = 0;
  if (v.choices().chance(30) || !(t <= in.ray.tmax)) in.ray.tmax = t;  // a segment that ends on the boundary
}

Features Query<RayAabbInput>::features(const RayAabbInput& in) {
  Features f;
  for (int k = 0; k < 3; ++k) f.parallel |= in.ray.dir[k] == 0 || std::isinf(1.0 / in.ray.dir[k]);
  f.degenerate = is_zero(in.ray.dir) || in.ray.tmin == in.ray.tmax || zero_extent(in.box);
  return f;
}

std::span<const std::string_view> Query<RayAabbInput>::configurations() { return kConfigurations; }

void Query<RayAabbInput>::recognise(const RayAabbInput& in, Configurations& found) {
  found.margins();
  const Ray& r = in.ray;
  const double d = max_abs(r.dir);
  bool par = false, nearly = false;
  for (int k = 0; k < 3; ++k) {
    const bool zero = r.dir[k] == 0 || std::isinf(1.0 / r.dir[k]);
    par |= zero;
    nearly |= !zero && std::fabs(r.dir[k]) <= kNearlyParallel * d;
  }
  found.add("parallel to a slab", par);
  found.add("nearly parallel to a slab", nearly);
  const Vec3 half = 0.5 * (in.box.hi - in.box.lo), center = 0.5 * (in.box.lo + in.box.hi);
  const double size = max_abs(half);
  double gap = 0;  // from the origin to the box, per axis at most
  for (int k = 0; k < 3; ++k) gap = std::max({gap, in.box.lo[k] - r.origin[k], r.origin[k] - in.box.hi[k]});
  found.add("from far away", size > 0 && gap >= kFar * size);
  found.negative_parameters();
  found.add("segment", std::isfinite(r.tmax) && r.tmax > 0);
  found.add("zero direction", d == 0);
  found.boxes(half);
  found.far(max_abs(center), size);
}

std::span<const BoundTerm> Query<RayAabbInput>::bound_terms() { return kBoundTerms; }

void Query<RayAabbInput>::probe(const RayAabbInput& in, std::vector<bounds::Records>& records) {
  intersect_ray_aabb(in.ray, in.box, bounds::next_call(records));
}

}  // namespace cc::harness
