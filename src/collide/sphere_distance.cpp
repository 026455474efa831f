#include "collide/sphere_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide/sphere_distance_bound.h"

namespace cc {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Separation outside_the_domain() {
  const Vec3 nan{kNan, kNan, kNan};
  return {kNan, nan, nan, kInf, kInf};
}

// |v| and v / |v|: the length within 2.6u of |v| (three-term sum of squares 3u, square root
// u/2 more), each component of the direction within 2u more (a reciprocal and a product). When
// the largest component lies in [2^-500, 2^500] the squares are taken as they are: none
// overflows, the largest is normal, and those that underflow err by 2^-1074 against a sum of
// at least 2^-1000. Otherwise v is first scaled by the power of two that brings its largest
// component into [1, 2), exactly, and the length scaled back (exact unless subnormal). A zero v
// has length 0 and no direction (zero).
struct LengthAndDirection {
  double length = 0;
  Vec3 direction;
};
LengthAndDirection length_and_direction(const Vec3& v) {
  const double m = max_abs(v);
  if (m >= 0x1p-500 && m <= 0x1p500) {
    const double n = std::sqrt(fp::sum3(v.x * v.x, v.y * v.y, v.z * v.z));
    const double inverse = 1 / n;
    return {n, {v.x * inverse, v.y * inverse, v.z * inverse}};
  }
  if (m == 0) return {};
  const int e = fp::exponent_of(m);
  const Vec3 s{fp::scale2(v.x, -e), fp::scale2(v.y, -e), fp::scale2(v.z, -e)};
  const double n = std::sqrt(fp::sum3(s.x * s.x, s.y * s.y, s.z * s.z));
  const double inverse = 1 / n;
  return {fp::scale2(n, e), {s.x * inverse, s.y * inverse, s.z * inverse}};
}

bool in_domain(const Sphere& s) { return finite(s.center) && fp::finite(s.radius) && s.radius >= 0; }

}  // namespace

Separation distance_sphere_sphere(const Sphere& a, const Sphere& b) {
  if (!in_domain(a) || !in_domain(b)) return outside_the_domain();
  const Vec3 d = b.center - a.center;  // swapping a and b negates d exactly
  LengthAndDirection ld = length_and_direction(d);
  if (ld.length == 0) ld.direction = {1, 0, 0};  // concentric: every direction is a shortest one
  const double reach = a.radius + b.radius;
  const bounds::SphereDistanceBound bound{ld.length, reach, std::max(max_abs(a.center), max_abs(b.center)),
                                          std::max(a.radius, b.radius)};
  return {ld.length - reach, a.center + a.radius * ld.direction, b.center - b.radius * ld.direction,
          bound.distance(), bound.point()};
}

Separation distance_sphere_obb(const Sphere& a, const Obb& b) {
  if (!in_domain(a) || !finite(b.center) || !finite(b.half) || !finite(b.axes) || !(b.half.x >= 0) ||
      !(b.half.y >= 0) || !(b.half.z >= 0)) {
    return outside_the_domain();
  }
  const Vec3 d = a.center - b.center;
  const Vec3 p = transpose_times(b.axes, d);  // the centre in the box's frame
  const bool inside = std::fabs(p.x) <= b.half.x && std::fabs(p.y) <= b.half.y && std::fabs(p.z) <= b.half.z;
  Vec3 q;        // the witness on the box, in its frame
  Vec3 outward;  // from q toward the centre (outside) or the face's outward normal (inside), in the frame
  double reach;  // the centre's distance to q, signed: negative inside
  if (!inside) {
    q = {std::clamp(p.x, -b.half.x, b.half.x), std::clamp(p.y, -b.half.y, b.half.y),
         std::clamp(p.z, -b.half.z, b.half.z)};
    const LengthAndDirection ld = length_and_direction(p - q);
    reach = ld.length;
    outward = ld.direction;
  } else {
    // The nearest face: the least h_i - |p_i| (on a tie the first axis, the + side).
    int nearest = 0;
    double least = b.half.x - std::fabs(p.x);
    for (int i = 1; i < 3; ++i) {
      const double room = b.half[i] - std::fabs(p[i]);
      if (room < least) least = room, nearest = i;
    }
    q = p;
    const double side = p[nearest] < 0 ? -1.0 : 1.0;
    q[nearest] = side * b.half[nearest];
    outward[nearest] = side;
    reach = -least;
  }
  const Vec3 world_outward = b.axes * outward;
  const bounds::SphereObbDistanceBound bound{norm1(d), norm1(b.half), a.radius,
                                             std::max(max_abs(a.center), max_abs(b.center))};
  return {reach - a.radius, a.center - a.radius * world_outward, b.center + b.axes * q, bound.distance(),
          bound.point()};
}

}  // namespace cc
