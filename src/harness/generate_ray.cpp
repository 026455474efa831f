// Generator for ray_aabb: rays parallel to a slab with the origin on, inside or just outside
// it; rays aimed at a corner, an edge or a face (exactly, or up to rounding); rays starting
// inside; segments ending on the boundary; tmax = 0; empty parameter ranges; lines (tmin =
// -inf); zero directions.
#include <cmath>
#include <limits>

#include "harness/generate_detail.h"

namespace cc::harness::detail {
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

}  // namespace

RayAabbInput generate_ray_aabb(ValueSource& v, const GenerateOptions& options) {
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
    case 2: {  // aimed at a boundary point; a segment may end exactly there
      // Simple values make o + t d exact, so the segment ends on the boundary exactly and the
      // slab parameters are often exact too; generic ones make it end there up to the rounding
      // of the origin, with slab parameters that round either way of tmax.
      const Vec3 target = draw_boundary_point(v, in.box);
      const bool generic = v.choices().chance(30);
      r.dir = generic ? v.point() : simple_direction(v);
      const double t = generic ? v.length() : std::ldexp(1.0, v.small_int(4));
      r.origin = target - t * r.dir;
      if (v.choices().chance(40)) r.tmax = v.choices().chance(70) ? t : v.nudge(t);
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

}  // namespace cc::harness::detail
