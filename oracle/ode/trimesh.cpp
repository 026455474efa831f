#include "oracle/ode/trimesh.h"

#include <algorithm>

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
  // dCollide writes only the contacts it reports, so one buffer per thread, made once, holds
  // them (zeroing a fresh 6 MB for every call took three quarters of a case of two triangles).
  static thread_local std::vector<dContactGeom> buffer(kMost);
  const int found = dCollide(a, b, kMost, buffer.data(), sizeof(dContactGeom));
  return {buffer.begin(), buffer.begin() + std::max(found, 0)};
}

}  // namespace cc::ode_oracle
