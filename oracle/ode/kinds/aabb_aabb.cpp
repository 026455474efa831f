// aabb_aabb's second opinion from ODE: dCollide on two axis-aligned dBox geoms, as an ODE user
// tests two boxes (ODE has no AABB-AABB call of its own: its spaces compare geoms' AABBs
// inside dSpaceCollide, asked of frames of boxes). A fair counterpart with a rounding band: each box
// becomes a centre fl((lo + hi) / 2) and sides fl(hi - lo), each within u of the scale, so the
// box ODE sees differs from the given one by up to 2u of the scale on every face; with identity
// rotations dBoxBox's face axes are exact sums |c_b - c_a| - (a + b) (two roundings, 4u of the
// scale) and its edge axes are all zero: 2^-46 two-sided. Boxes with NaN, infinite or inverted
// bounds are not asked (a centre or a side would be NaN, infinite or negative). dBoxBox's contact
// clipping misses boxes touching only along an edge or at a corner (within the band, at margin
// 0) and, beyond it, flat boxes and boxes of subnormal size (as with oriented boxes): defects of ODE's.
// (Below the normal range the centre's halving rounds by up to 2.5e-324, absolute: beyond the
// band for boxes of subnormal size.)
#include <cmath>

#include "oracle/ode/convert.h"
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {
namespace {

Opinion collide_boxes(const harness::AabbAabbInput& in) {
  Geom boxes[2];
  const Aabb* given[2] = {&in.a, &in.b};
  for (int i = 0; i < 2; ++i) {
    const Aabb& box = *given[i];
    const Vec3 center = 0.5 * (box.lo + box.hi), sides = box.hi - box.lo;
    for (int k = 0; k < 3; ++k) {
      if (!(std::isfinite(center[k]) && std::isfinite(sides[k]) && box.lo[k] <= box.hi[k])) {
        return not_applicable("a box with NaN, infinite or inverted bounds");
      }
    }
    boxes[i].reset(dCreateBox(nullptr, sides.x, sides.y, sides.z));
    dGeomSetPosition(boxes[i].get(), center.x, center.y, center.z);
  }
  return answered(any_contact(boxes[0].get(), boxes[1].get()));
}

}  // namespace

template <>
const std::vector<Party<harness::AabbAabbInput>>& ode_parties() {
  static const std::vector<Party<harness::AabbAabbInput>> parties = {ode_party<harness::AabbAabbInput>(
      "ode.dCollide(dBox,dBox)",
      {0x1p-46, BandSides::two_sided, 0,
       "each box as a rounded centre and sides (2u of the scale per face), then dBoxBox's exact-axis face tests (4u)"},
      collide_boxes)};
  return parties;
}

}  // namespace cc::ode_oracle
