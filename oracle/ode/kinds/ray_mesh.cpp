// ray_mesh's second opinion from ODE: a dGeomRay against the mesh as a dTriMesh (trimesh.h)
// through dCollide, the ray asked for its closest hit (dGeomRaySetClosestHit), back faces not
// culled; its answer the face of the contact (side1; no t is compared). As for the ray-box party, only
// rays with tmin = 0 are asked, a finite ray is a segment of length tmax |dir|, an infinite one
// a ray of twice the distance from its origin to the farthest vertex (past every point it can
// meet the mesh at). OPCODE's RayCollider tests the faces in single precision (vertices, origin
// and direction rounded to float, 2^-24 of the scale; Moller-Trumbore in float): 2^-20
// two-sided. A face whose determinant |e1 . (d x e2)| is at most 1e-6 min(|e1|^2, |e2|^2) (a
// ray grazing it within about 1e-6 rad, or a face of zero area) is never hit, and a barycentric
// coordinate of -0 is a miss (its sign bit is tested): beyond the band, on edges and grazing rays;
// so is a direction below 1/DBL_MAX, which dSafeNormalize3 turns into NaN.
#include <algorithm>
#include <cmath>

#include "oracle/ode/parties.h"
#include "oracle/ode/trimesh.h"

namespace cc::ode_oracle {
namespace {

Opinion ray_trimesh(const harness::RayMeshInput& in) {
  const Ray& r = in.ray;
  if (in.mesh.mesh == nullptr) return not_applicable("no mesh");
  const Mesh& mesh = *in.mesh.mesh;
  if (!(r.tmin == 0)) return not_applicable("tmin != 0 (ODE's ray starts at its origin)");
  if (!(r.tmax >= 0)) return not_applicable("an empty parameter range (tmin > tmax)");
  if (!finite(r.origin) || !finite(r.dir)) return not_applicable("a NaN or infinite origin or direction");
  if (r.dir == Vec3{0, 0, 0}) return not_applicable("a zero direction (dGeomRaySet normalises it)");
  double farthest = 0;
  for (const Vec3& v : mesh.vertices) {
    if (!finite(v)) return not_applicable("a NaN or infinite vertex");
    farthest = std::max(farthest, length_of(v - r.origin));
  }
  const double length = std::isinf(r.tmax) ? 2 * farthest : r.tmax * length_of(r.dir);
  if (!std::isfinite(length)) return not_applicable("a ray length that overflows");
  if (mesh.faces.empty()) return answered(false);
  const TriMesh trimesh(mesh);
  Geom ray(dCreateRay(nullptr, length));
  dGeomRaySet(ray.get(), r.origin.x, r.origin.y, r.origin.z, r.dir.x, r.dir.y, r.dir.z);
  dGeomRaySetFirstContact(ray.get(), 0);
  dGeomRaySetBackfaceCull(ray.get(), 0);
  dGeomRaySetClosestHit(ray.get(), 1);
  dContactGeom contact;
  if (dCollide(ray.get(), trimesh.geom(), 1, &contact, sizeof contact) == 0) return answered(false);
  const int face = contact.g1 == trimesh.geom() ? contact.side1 : contact.side2;
  if (face < 0) return failed("a contact naming no triangle");
  harness::Answer a = harness::Answer::of(true);
  a.pairs = {{trimesh.face_of(face), 0}};
  return answered(a);
}

}  // namespace

template <>
const std::vector<Party<harness::RayMeshInput>>& ode_parties() {
  static const std::vector<Party<harness::RayMeshInput>> parties = {ode_party<harness::RayMeshInput>(
      "ode.dCollide(dRay,dTriMesh)",
      {0x1p-20, BandSides::two_sided, 0,
       "OPCODE's ray-triangle test in single precision (2^-24 of the scale); grazing rays (1e-6) and zero-area faces "
       "never hit"},
      ray_trimesh)};
  return parties;
}

}  // namespace cc::ode_oracle
