// The signed distance of a ball to another ball or to an oriented box, with witness points
// (separation.h).
#pragma once

#include <algorithm>
#include <cmath>

#include "collide/length.h"
#include "collide/obb.h"
#include "collide/separation.h"
#include "collide/sphere.h"
#include "collide/sphere_distance_bound.h"

namespace cc {

/// The signed distance between two balls: |b.center - a.center| - a.radius - b.radius, with
/// witness points on the line of the centres. Concentric balls: any direction is a shortest
/// one; the x axis is taken. Swapping a and b swaps the witnesses bit for bit (concentric
/// balls aside) and gives the same distance.
///  - Domain: finite inputs of magnitude at most 2^500, radii >= 0.
///  - distance_error: 8u (|b.center - a.center| + a.radius + b.radius), plus the subnormal
///    slack; point_error: 16u (the larger centre coordinate + the larger radius), plus the slack.
inline Separation distance_sphere_sphere(const Sphere& a, const Sphere& b);

/// The signed distance between a ball (a) and a box (b): the distance from the centre to the box
/// minus the radius, outside; minus the centre's distance to the box's boundary minus the radius,
/// inside. A centre inside the box (its boundary included) is pushed out through a nearest face
/// (on a tie, the first axis, the + side). on_b is the centre's nearest point of the box's
/// boundary; on_a the ball's point nearest the box outside (the centre less the radius along
/// the direction from on_b to the centre), and inside the centre less the radius along the
/// face's outward normal.
///  - Domain: finite inputs of magnitude at most 2^500, radius and half extents >= 0, axes
///    orthonormal to within kObbOrthonormalTolerance (eta). The box is the parallelepiped its
///    axes span; the bounds hold for it.
///  - distance_error: 16u (|d|_1 + |half|_1 + radius) + 8 eta (|d|_1 + |half|_1), d the centre
///    offset, plus the subnormal slack; point_error: 16u (both centres' largest coordinate + |d|_1
///    + |half|_1 + radius) + 4 eta (radius + |d|_1 + |half|_1), plus the slack.
inline Separation distance_sphere_obb(const Sphere& a, const Obb& b);

// The definitions, inline: called once per pair of shapes, these are short enough that a call
// costs as much as the work (and the caller keeps only what it reads).
namespace detail {

// Every input finite, the radii and half extents >= 0 (the axes' orthonormality is the
// caller's), with no branch per value (x - x is 0 for a finite x, NaN else).
inline bool in_domain(const Sphere& a, const Sphere& b) {
  const Vec3 zero = (a.center - a.center) + (b.center - b.center) + Vec3{a.radius - a.radius, b.radius - b.radius, 0};
  return finite(zero) && std::min(a.radius, b.radius) >= 0;
}
inline bool in_domain(const Sphere& a, const Obb& b) {
  const Vec3 zero = (a.center - a.center) + Vec3{a.radius - a.radius, 0, 0};
  return finite(zero) && a.radius >= 0 && cc::in_domain(b);
}

template <class Records>
Separation sphere_sphere(const Sphere& a, const Sphere& b, Records& records) {
  if (!in_domain(a, b)) return Separation::outside_the_domain();
  const Vec3 d = b.center - a.center;  // swapping a and b negates d exactly
  LengthAndDirection ld = length_and_direction(d);
  if (ld.length == 0) ld.direction = {1, 0, 0};  // concentric: every direction is a shortest one
  const double reach = a.radius + b.radius;
  const bounds::SphereDistanceBound bound{ld.length, reach, std::max(max_abs(a.center), max_abs(b.center)),
                                          std::max(a.radius, b.radius)};
  const Separation s{ld.length - reach, a.center + a.radius * ld.direction, b.center - b.radius * ld.direction,
                     bound.distance(), bound.point()};
  records.add(bounds::SphereSeparation{a, b, s, bound});
  return s;
}

template <class Records>
Separation sphere_obb(const Sphere& a, const Obb& b, Records& records) {
  if (!in_domain(a, b)) return Separation::outside_the_domain();
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
  const Separation s{reach - a.radius, a.center - a.radius * world_outward, b.center + b.axes * q, bound.distance(),
                     bound.point()};
  records.add(bounds::SphereObbSeparation{a, b, s, bound});
  return s;
}

}  // namespace detail

inline Separation distance_sphere_sphere(const Sphere& a, const Sphere& b) {
  bounds::NoRecords none;
  return detail::sphere_sphere(a, b, none);
}

inline Separation distance_sphere_obb(const Sphere& a, const Obb& b) {
  bounds::NoRecords none;
  return detail::sphere_obb(a, b, none);
}

}  // namespace cc
