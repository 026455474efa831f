#include "oracle/ode/trimesh.h"

namespace cc::ode_oracle {

TriMesh::TriMesh(const Mesh& mesh, const RigidTransform& pose) {
  vertices_.reserve(3 * mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) vertices_.insert(vertices_.end(), {v.x, v.y, v.z});
  indices_.reserve(3 * mesh.size());
  for (const auto& f : mesh.faces) indices_.insert(indices_.end(), {f[0], f[1], f[2]});
  faces_ = static_cast<std::uint32_t>(mesh.size());
  if (mesh.size() == 1) indices_.insert(indices_.end(), indices_.begin(), indices_.end());  // the face twice
  data_ = dGeomTriMeshDataCreate();
  dGeomTriMeshDataBuildDouble(data_, vertices_.data(), 3 * sizeof(double), static_cast<int>(mesh.vertices.size()),
                              indices_.data(), static_cast<int>(indices_.size()), 3 * sizeof(dTriIndex));
  geom_.reset(dCreateTriMesh(nullptr, data_, nullptr, nullptr, nullptr));
  dMatrix3 r;
  to_ode(pose.rotation, r);
  dGeomSetRotation(geom_.get(), r);
  dGeomSetPosition(geom_.get(), pose.translation.x, pose.translation.y, pose.translation.z);
}

TriMesh::~TriMesh() {
  geom_.reset();
  dGeomTriMeshDataDestroy(data_);
}

std::vector<dContactGeom> contacts(dGeomID a, dGeomID b) {
  constexpr int kMost = 0xffff;  // NUMC_MASK: the most contacts one dCollide reports
  std::vector<dContactGeom> out(kMost);
  out.resize(static_cast<std::size_t>(dCollide(a, b, kMost, out.data(), sizeof(dContactGeom))));
  return out;
}

}  // namespace cc::ode_oracle
