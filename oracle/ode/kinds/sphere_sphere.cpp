// sphere_sphere's second opinion from ODE: dCollide on two dSphere geoms (dCollideSpheres: a
// contact unless d > r_a + r_b, d the square root of the rounded squares of the rounded
// difference of the centres, the sum of the radii rounded). As Bullet's test: d within about
// 4u of the distance, the sum within u, so a misjudged case lies within 5u of (d + r_a + r_b),
// at most 2^-47 of the scale; a difference whose squares underflow reads as d = 0, a hit beyond
// any band (a defect of ODE's). Negative, NaN or infinite inputs are not asked (ODE asserts
// radius >= 0).
#include <cmath>

#include "oracle/ode/convert.h"
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {
namespace {

Geom sphere_geom(const Sphere& s) {
  Geom g(dCreateSphere(nullptr, s.radius));
  dGeomSetPosition(g.get(), s.center.x, s.center.y, s.center.z);
  return g;
}

Opinion collide_spheres(const harness::SphereSphereInput& in) {
  for (const Sphere* s : {&in.a, &in.b}) {
    if (!(s->radius >= 0 && std::isfinite(s->radius) && finite(s->center))) {
      return not_applicable("a negative, NaN or infinite radius or centre");
    }
  }
  const Geom a = sphere_geom(in.a), b = sphere_geom(in.b);
  return answered(any_contact(a.get(), b.get()));
}

}  // namespace

template <>
const std::vector<Party<harness::SphereSphereInput>>& ode_parties() {
  static const std::vector<Party<harness::SphereSphereInput>> parties = {ode_party<harness::SphereSphereInput>(
      "ode.dCollide(dSphere,dSphere)",
      {0x1p-47, BandSides::two_sided, 0,
       "the centres' distance as a square root of rounded squares (4u) against the rounded sum of the radii (u)"},
      collide_spheres)};
  return parties;
}

}  // namespace cc::ode_oracle
