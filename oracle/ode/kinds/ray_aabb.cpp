// ray_aabb's second opinion from ODE: a dGeomRay against an axis-aligned dBox through dCollide
// (dCollideRayBox; a hit when it returns a contact). ODE's ray starts at its origin, runs along
// its direction normalised (dGeomRaySet) for its length, and reports where it crosses the box's
// surface: the entry, or the exit for an origin inside. So:
//  - only rays with tmin = 0 are asked (moving the origin to origin + tmin dir would round it);
//  - a finite ray is a segment of length tmax |dir|; an infinite one is given a length of twice
//    the distance from its origin to the box's farthest corner, past every point it can meet
//    the box at (a length that overflows is not asked);
//  - a finite segment whose origin lies in the closed box (compared exactly) is not asked: ODE
//    reports only a crossing of the surface, so a segment inside the box is a miss by design;
//  - a zero direction, NaN, infinite or inverted bounds are not asked.
// The box becomes a centre and sides, each rounded (2u of the scale per face); ODE moves the
// origin into the box's frame (u of 2 scales), normalises the direction (3u of its angle, moving
// a point by 3u of its distance), and compares slab parameters (-h - s) / v and (h - s) / v
// (3u of each) and the entry with the length (rounded, 2u): within about 16u of the scale:
// 2^-44 two-sided. No parameter is compared (ODE's depth is a distance along the ray). Beyond the
// band, a defect of ODE's: dSafeNormalize3 divides by the largest component's reciprocal, which
// overflows for a direction below 1/DBL_MAX (about 5.6e-309): the direction becomes NaN and the
// ray meets nothing.
#include <algorithm>
#include <cmath>

#include "oracle/ode/convert.h"
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {
namespace {

Opinion ray_box(const harness::RayAabbInput& in) {
  const Ray& r = in.ray;
  const Aabb& box = in.box;
  if (!(r.tmin == 0)) return not_applicable("tmin != 0 (ODE's ray starts at its origin)");
  if (!(r.tmax >= 0)) return not_applicable("an empty parameter range (tmin > tmax)");
  if (!finite(r.origin) || !finite(r.dir)) return not_applicable("a NaN or infinite origin or direction");
  if (r.dir == Vec3{0, 0, 0}) return not_applicable("a zero direction (dGeomRaySet normalises it)");
  const Vec3 center = 0.5 * (box.lo + box.hi), sides = box.hi - box.lo;
  for (int k = 0; k < 3; ++k) {
    if (!(std::isfinite(center[k]) && std::isfinite(sides[k]) && box.lo[k] <= box.hi[k])) {
      return not_applicable("a box with NaN, infinite or inverted bounds");
    }
  }
  double length = 0;
  if (std::isinf(r.tmax)) {
    double farthest = 0;
    for (int c = 0; c < 8; ++c) {
      const Vec3 corner{(c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z};
      farthest = std::max(farthest, length_of(corner - r.origin));
    }
    length = 2 * farthest;
  } else {
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside = inside && box.lo[k] <= r.origin[k] && r.origin[k] <= box.hi[k];
    if (inside)
      return not_applicable("a segment starting in the box (ODE's ray reports only a crossing of its surface)");
    length = r.tmax * length_of(r.dir);
  }
  if (!std::isfinite(length)) return not_applicable("a ray length that overflows");
  Geom ode_box(dCreateBox(nullptr, sides.x, sides.y, sides.z));
  dGeomSetPosition(ode_box.get(), center.x, center.y, center.z);
  Geom ray(dCreateRay(nullptr, length));
  dGeomRaySet(ray.get(), r.origin.x, r.origin.y, r.origin.z, r.dir.x, r.dir.y, r.dir.z);
  return answered(any_contact(ray.get(), ode_box.get()));
}

}  // namespace

template <>
const std::vector<Party<harness::RayAabbInput>>& ode_parties() {
  static const std::vector<Party<harness::RayAabbInput>> parties = {ode_party<harness::RayAabbInput>(
      "ode.dCollide(dRay,dBox)",
      {0x1p-44, BandSides::two_sided, 0,
       "box as rounded centre and sides, direction normalised, slab parameters and the length rounded: about 16u of "
       "the scale"},
      ray_box)};
  return parties;
}

}  // namespace cc::ode_oracle
