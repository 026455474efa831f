// ODE trimeshes of the library's meshes (internal to oracle/ode), for tri_tri, the mesh kinds
// and ray_mesh.
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
/// of them in single precision), placed by a pose (dGeomSetRotation, dGeomSetPosition).
class TriMesh {
 public:
  explicit TriMesh(const Mesh& mesh, const RigidTransform& pose = {});
  TriMesh(const TriMesh&) = delete;
  TriMesh& operator=(const TriMesh&) = delete;
  ~TriMesh();
  dGeomID geom() const { return geom_.get(); }

 private:
  std::vector<double> vertices_;
  std::vector<dTriIndex> indices_;
  dTriMeshDataID data_ = nullptr;
  Geom geom_;
};

/// Every contact ODE reports between two geoms (at most 65535, its limit).
std::vector<dContactGeom> contacts(dGeomID a, dGeomID b);

}  // namespace cc::ode_oracle
