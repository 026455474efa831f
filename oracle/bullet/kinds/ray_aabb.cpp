// ray_aabb's second opinions from Bullet: its two ray-box tests of LinearMath/btAabbUtil2.h.
//  - btRayAabb2, the slab test its dynamic AABB trees cast rays with (btDbvt::rayTest): the ray
//    origin + t dir for t in (lambda_min, lambda_max), given the direction's reciprocals as
//    Bullet's callers compute them (a zero component: BT_LARGE_FLOAT, 1e30, instead of an
//    infinity; a component whose reciprocal overflows: an infinity). Its last comparison is
//    strict: a ray touching the box only at t = tmax or t = tmin is a miss, a difference of
//    meaning (the library's ranges are closed) that a two-sided band holds. Each parameter
//    (b - o) * (1 / d) is rounded three times, within 3u of itself: as a growth of the box,
//    at most 3u |b - o| <= 6u of the scale on each side; 2^-48 leaves a factor of 2. What the
//    band does not hold is the stand-in 1e30 for 1/0: a ray parallel to a slab, outside it by
//    less than tmax / 1e30, is taken as crossing it.
//  - btRayAabb, the segment test of btCollisionWorld's ray casts against boxes: the segment from
//    origin + tmin dir to origin + tmax dir, with param = 1 (the whole segment), closed. It needs
//    finite tmin <= tmax; the segment's ends are rounded here (origin exactly when tmin = 0), so
//    it is not asked of segments reaching beyond 8 times the scale (the largest magnitude of
//    the box and the origin), whose ends' rounding is not the box's. Bullet then works in the
//    box's centre and half extents (each rounded, u of the scale), moves the ends by the centre
//    (u of 9 scales), and compares lambdas (-s - h) / r (3u of the segment's length, up to 18
//    scales): within 2^-44 of the scale (about 90u).
#include <LinearMath/btAabbUtil2.h>

#include <algorithm>
#include <cmath>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {

Opinion ray_aabb2(const harness::RayAabbInput& in) {
  const Ray& r = in.ray;
  btVector3 inverse;
  unsigned int sign[3];
  for (int i = 0; i < 3; ++i) {
    inverse[i] = r.dir[i] == 0.0 ? btScalar(BT_LARGE_FLOAT) : btScalar(1.0) / r.dir[i];  // as btDbvt::rayTest
    sign[i] = inverse[i] < 0.0;
  }
  const btVector3 bounds[2] = {to_bullet(in.box.lo), to_bullet(in.box.hi)};
  btScalar t_enter = 0;
  return answered(btRayAabb2(to_bullet(r.origin), inverse, sign, bounds, t_enter, r.tmin, r.tmax));
}


Opinion ray_aabb(const harness::RayAabbInput& in) {
  const Ray& r = in.ray;
  if (!std::isfinite(r.tmin) || !std::isfinite(r.tmax)) return not_applicable("a ray of infinite length (btRayAabb takes segments)");
  if (!(r.tmin <= r.tmax)) return not_applicable("an empty parameter range (tmin > tmax)");
  const Vec3 from = r.tmin == 0 ? r.origin : r.origin + r.tmin * r.dir, to = r.origin + r.tmax * r.dir;
  const double scale = std::max({max_abs(in.box.lo), max_abs(in.box.hi), max_abs(r.origin)});
  if (!(std::max(max_abs(from), max_abs(to)) <= 8 * scale)) {
    return not_applicable("the segment reaches beyond 8 times the scale of the box and the origin");
  }
  btScalar param = 1;
  btVector3 normal;
  return answered(btRayAabb(to_bullet(from), to_bullet(to), to_bullet(in.box.lo), to_bullet(in.box.hi), param, normal));
}

}  // namespace

template <>
const std::vector<Party<harness::RayAabbInput>>& bullet_parties() {
  static const std::vector<Party<harness::RayAabbInput>> parties = {
      {"bullet.btRayAabb2",
       {0x1p-48, BandSides::two_sided, 0,
        "each slab parameter (b - o) * (1 / d) rounded three times: a box grown or shrunk by 6u of the scale; "
        "touching at t = tmin or tmax is a miss (strict)"},
       ray_aabb2},
      {"bullet.btRayAabb",
       {0x1p-44, BandSides::two_sided, 0,
        "the segment's ends rounded (asked within 8 scales), the box as centre and half extents, lambdas "
        "(-s - h) / r: about 90u of the scale"},
       ray_aabb}};
  return parties;
}

}  // namespace cc::bullet_oracle
