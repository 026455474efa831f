// mesh_mesh_first's second opinion from ODE: the two meshes as dTriMeshes placed by their poses
// (trimesh.h) through dCollide, ODE's trimesh-trimesh collider (OPCODE's); a hit when it returns a
// contact, its pair the first contact's (side1, side2), the faces of a and b. ODE merges contacts
// at nearly the same point; each mesh's dTriTriMergeCallback keeps the pair already named, so every
// contact names a pair ODE found colliding (the all-pairs kind's unit says why only the first is
// compared). OPCODE finds candidate pairs with its AABB trees and triangle test in single precision
// (vertices and poses rounded to float: 2^-24 of the scale per coordinate, plane distances within
// 1e-6 snapped to 0), moving b into a's frame in float; ODE computes each pair's contact in double
// and drops pairs of depth < 0: 2^-20 two-sided. A face of zero area never collides (no plane):
// beyond the band; so are contacts for pairs apart (as with single triangles: ODE's contact step
// measures depth along the face normals only).
#include "oracle/ode/parties.h"
#include "oracle/ode/trimesh.h"

namespace cc::ode_oracle {
namespace {

int keep_first(dGeomID, int first, int) { return first; }

Opinion collide_meshes(const harness::MeshMeshFirstInput& in) {
  const harness::MeshPair& m = in.meshes;
  if (m.a.mesh == nullptr || m.b.mesh == nullptr) return not_applicable("no mesh");
  if (m.a.mesh->size() == 0 || m.b.mesh->size() == 0) return not_applicable("a mesh without triangles");
  for (const Mesh* mesh : {m.a.mesh.get(), m.b.mesh.get()}) {
    for (const Vec3& v : mesh->vertices) {
      if (!finite(v)) return not_applicable("a NaN or infinite vertex");
    }
  }
  const TriMesh a(*m.a.mesh, m.pose_a), b(*m.b.mesh, m.pose_b);
  dGeomTriMeshSetTriMergeCallback(a.geom(), keep_first);
  dGeomTriMeshSetTriMergeCallback(b.geom(), keep_first);
  const std::vector<dContactGeom> found = contacts(a.geom(), b.geom());
  if (found.empty()) return answered(false);
  const dContactGeom& first = found.front();
  if (first.side1 < 0 || first.side2 < 0) return failed("a contact naming no pair of triangles");
  harness::Answer answer = harness::Answer::of(true);
  answer.pairs = {{a.face_of(first.side1), b.face_of(first.side2)}};
  return answered(answer);
}

}  // namespace

template <>
const std::vector<Party<harness::MeshMeshFirstInput>>& ode_parties() {
  static const std::vector<Party<harness::MeshMeshFirstInput>> parties = {ode_party<harness::MeshMeshFirstInput>(
      "ode.dCollide(dTriMesh,dTriMesh)",
      {0x1p-20, BandSides::two_sided, 0,
       "OPCODE's trees and triangle test in single precision (2^-24 per coordinate, b moved in float), then ODE's "
       "contact in double; a zero-area face never collides"},
      collide_meshes)};
  return parties;
}

}  // namespace cc::ode_oracle
