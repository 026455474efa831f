#include "collide/sphere_distance.h"

#include <algorithm>
#include <cmath>

#include "collide/length.h"
#include "collide/record_sink.h"
#include "collide/sphere_distance_bound.h"

namespace cc {
namespace {

bool in_domain(const Sphere& s) { return finite(s.center) && fp::finite(s.radius) && s.radius >= 0; }

template <class Records>
Separation sphere_sphere(const Sphere& a, const Sphere& b, Records& records) {
  if (!in_domain(a) || !in_domain(b)) return Separation::outside_the_domain();
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
  if (!in_domain(a) || !finite(b.center) || !finite(b.half) || !finite(b.axes) || !(b.half.x >= 0) ||
      !(b.half.y >= 0) || !(b.half.z >= 0)) {
    return Separation::outside_the_domain();
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
  const Separation s{reach - a.radius, a.center - a.radius * world_outward, b.center + b.axes * q, bound.distance(),
                     bound.point()};
  records.add(bounds::SphereObbSeparation{a, b, s, bound});
  return s;
}

}  // namespace

Separation distance_sphere_sphere(const Sphere& a, const Sphere& b) {
  bounds::NoRecords none;
  return sphere_sphere(a, b, none);
}

Separation distance_sphere_sphere(const Sphere& a, const Sphere& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return sphere_sphere(a, b, into);
}

Separation distance_sphere_obb(const Sphere& a, const Obb& b) {
  bounds::NoRecords none;
  return sphere_obb(a, b, none);
}

Separation distance_sphere_obb(const Sphere& a, const Obb& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return sphere_obb(a, b, into);
}

}  // namespace cc
