// tri_tri's second opinion from ODE: two one-triangle dTriMeshes (trimesh.h) through dCollide, ODE's
// trimesh-trimesh collider (OPCODE's, the "new collider" of Debian's build); a hit when it
// returns a contact. OPCODE finds the candidate pair with its AABB trees and its triangle overlap
// test, in single precision (the vertices and the poses rounded to float: 2^-24 of the scale per
// coordinate, and the test's plane distances within 1e-6 snapped to 0); ODE then computes the
// pair's contact in double (each triangle's normalised plane, the other clipped by its edge
// planes, the deepest points; a pair of depth < 0 gives none): 2^-20 two-sided. A triangle of
// zero area has no plane (dSafeNormalize3 fails) and never collides: beyond the band. (Each mesh
// holds its triangle twice: OPCODE crashes on a tree of one triangle, see trimesh.h.) A 90-second
// campaign found it reporting contacts for triangles apart by up to 1e-2 of the scale, beyond
// any rounding: defects of ODE's (OPCODE accepts the pair, and ODE's contact step does not
// test separation: it clips each triangle by the other's edge planes and measures depth along
// the two face normals only, its edge-edge axes commented out).
#include "oracle/ode/parties.h"
#include "oracle/ode/trimesh.h"

namespace cc::ode_oracle {
namespace {

Mesh one_triangle(const Triangle& t) { return {{t.v[0], t.v[1], t.v[2]}, {{0, 1, 2}}}; }

Opinion collide_triangles(const harness::TriTriInput& in) {
  for (const Triangle* t : {&in.a, &in.b}) {
    for (const Vec3& v : t->v) {
      if (!finite(v)) return not_applicable("a NaN or infinite vertex");
    }
  }
  const TriMesh a(one_triangle(in.a)), b(one_triangle(in.b));
  return answered(!contacts(a.geom(), b.geom()).empty());
}

}  // namespace

template <>
const std::vector<Party<harness::TriTriInput>>& ode_parties() {
  static const std::vector<Party<harness::TriTriInput>> parties = {ode_party<harness::TriTriInput>(
      "ode.dCollide(dTriMesh,dTriMesh)",
      {0x1p-20, BandSides::two_sided, 0,
       "OPCODE's triangle test in single precision (2^-24 per coordinate, plane distances within 1e-6 snapped to 0), "
       "then ODE's contact in double; a zero-area triangle never collides"},
      collide_triangles)};
  return parties;
}

}  // namespace cc::ode_oracle
