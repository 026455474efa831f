// obb_obb's second opinions from ODE: dBoxTouchesBox, and dCollide on two dBox geoms (dBoxBox, a
// hit when it returns a contact). Each box is given its sides 2 half (exact) and its frame made
// proper (convert.h). Both evaluate the 15 separating axes of Gottschalk et al. in plain floating
// point, closed (an axis separates only when |p . n| exceeds the radii), with no padding of
// |R_ij|: on the six face axes each side is a sum of four rounded products, within about 10u of
// the scale, and axes orthonormal to 2^-48 move the radii by 2^-46 of the extents: 2^-40
// two-sided, the width of FCL's port of the same test. The nine edge axes are not normalised
// before the comparison: for two nearly parallel edges, u_i x v_j is tiny and the rounding of the
// R_ij (about u) can exceed both sides, so an overlapping pair may be separated by a degenerate
// axis; that lies beyond the band, a defect of ODE's (the ports in Bullet and FCL add 1e-5 or
// 10 eps to every |R_ij| for it). dBoxBox then clips the incident face to the reference face and
// keeps points of depth >= 0, rounded about u of the scale: inside the same band; but a box with
// a side 0 (flat, a segment, a point) often leaves its clipping no point, and then no contact:
// a defect of ODE's beyond any band, which Bullet's port (btBoxBoxDetector) shares, and boxes
// touching only along an edge or at a corner give none either (within the band). Its cullPoints
// can fail an internal assertion ("*iret != i0"), a failed opinion (ode_call.h). Negative,
// NaN or infinite inputs are not asked (ODE asserts sides >= 0).
#include <cmath>
#include <optional>
#include <string>

#include "oracle/ode/convert.h"
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {
namespace {

std::optional<std::string> not_asked(const harness::ObbObbInput& in) {
  for (const Obb* b : {&in.a, &in.b}) {
    for (int k = 0; k < 3; ++k) {
      if (!(b->half[k] >= 0 && std::isfinite(b->half[k]) && std::isfinite(b->center[k]))) {
        return "a negative, NaN or infinite half extent or centre";
      }
      for (int j = 0; j < 3; ++j) {
        if (!std::isfinite(b->axes(k, j))) return "a NaN or infinite axis";
      }
    }
  }
  return std::nullopt;
}

Opinion touches_box(const harness::ObbObbInput& in) {
  if (auto why = not_asked(in)) return not_applicable(*why);
  dMatrix3 ra, rb;
  to_ode(proper_frame(in.a.axes), ra), to_ode(proper_frame(in.b.axes), rb);
  const dVector3 pa = {in.a.center.x, in.a.center.y, in.a.center.z, 0};
  const dVector3 pb = {in.b.center.x, in.b.center.y, in.b.center.z, 0};
  const dVector3 sa = {2 * in.a.half.x, 2 * in.a.half.y, 2 * in.a.half.z, 0};
  const dVector3 sb = {2 * in.b.half.x, 2 * in.b.half.y, 2 * in.b.half.z, 0};
  return answered(dBoxTouchesBox(pa, ra, sa, pb, rb, sb) != 0);
}

Opinion collide_boxes(const harness::ObbObbInput& in) {
  if (auto why = not_asked(in)) return not_applicable(*why);
  const Geom a = box_geom(in.a), b = box_geom(in.b);
  return answered(any_contact(a.get(), b.get()));
}

}  // namespace

template <>
const std::vector<Party<harness::ObbObbInput>>& ode_parties() {
  constexpr Band kBand{0x1p-40, BandSides::two_sided, 0,
                       "15 axes in floating point, |R_ij| unpadded: face axes about 10u of the scale; a nearly "
                       "parallel edge pair's unnormalised axis can separate falsely (beyond the band)"};
  static const std::vector<Party<harness::ObbObbInput>> parties = {
      ode_party<harness::ObbObbInput>("ode.dBoxTouchesBox", kBand, touches_box),
      ode_party<harness::ObbObbInput>(
          "ode.dCollide(dBox,dBox)",
          {0x1p-40, BandSides::two_sided, 0,
           "dBoxBox: dBoxTouchesBox's axes (|R_ij| unpadded), then contact points of depth >= 0 (u of the scale)"},
          collide_boxes)};
  return parties;
}

}  // namespace cc::ode_oracle
