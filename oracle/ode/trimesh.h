// ODE trimeshes of the library's meshes (internal to oracle/ode), for the kinds on triangles,
// meshes and rays against meshes.
#pragma once

#include <ode/ode.h>

#include <cstdint>
#include <vector>

#include "collide/mesh.h"
#include "collide/rigid_transform.h"
#include "oracle/ode/convert.h"

namespace cc::ode_oracle {

/// A dTriMesh of a mesh's faces, in order (ODE's triangle index f is the mesh's face f), built
/// with dGeomTriMeshDataBuildDouble from the vertices as given (ODE's OPCODE builds its AABB tree
/// of them in single precision), placed by a pose (dGeomSetRotation, dGeomSetPosition). A mesh of
/// one face is given it twice: OPCODE's collision tree of a single triangle has no node, and its
/// AABBTreeCollider::Collide reads one (a SIGSEGV in ODE 0.16.2); face_of maps ODE's index back.
class TriMesh {
 public:
  explicit TriMesh(const Mesh& mesh, const RigidTransform& pose = {});
  TriMesh(const TriMesh&) = delete;
  TriMesh& operator=(const TriMesh&) = delete;
  ~TriMesh();
  dGeomID geom() const { return geom_.get(); }
  /// The mesh's face of ODE's triangle index (>= 0).
  std::uint32_t face_of(int side) const { return static_cast<std::uint32_t>(side) % faces_; }

 private:
  std::vector<double> vertices_;
  std::vector<dTriIndex> indices_;
  std::uint32_t faces_ = 1;
  dTriMeshDataID data_ = nullptr;
  Geom geom_;
};

/// Every contact ODE reports between two geoms (at most 65535, its limit).
std::vector<dContactGeom> contacts(dGeomID a, dGeomID b);

}  // namespace cc::ode_oracle
