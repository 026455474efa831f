#include "bench/fcl_models.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/kDOP.h>
#include <fcl/math/bv/kIOS.h>

#include <vector>

namespace cc::bench {
namespace {

template <class BV>
std::size_t build(const Mesh& mesh) {
  std::vector<fcl::Vector3d> vertices;
  vertices.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) vertices.emplace_back(v.x, v.y, v.z);
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.faces.size());
  for (const auto& f : mesh.faces) triangles.emplace_back(f[0], f[1], f[2]);
  fcl::BVHModel<BV> model;
  model.beginModel(static_cast<int>(triangles.size()), static_cast<int>(vertices.size()));
  model.addSubModel(vertices, triangles);
  model.endModel();
  return static_cast<std::size_t>(model.num_vertices) * sizeof(fcl::Vector3d) +
         static_cast<std::size_t>(model.num_tris) * (sizeof(fcl::Triangle) + sizeof(unsigned int)) +
         static_cast<std::size_t>(model.getNumBVs()) * sizeof(fcl::BVNode<BV>);
}

}  // namespace

std::string_view to_string(FclBv bv) {
  switch (bv) {
    case FclBv::aabb: return "aabb";
    case FclBv::obb: return "obb";
    case FclBv::kdop16: return "kdop16";
    case FclBv::kdop18: return "kdop18";
    case FclBv::kdop24: return "kdop24";
    case FclBv::kios: break;
  }
  return "kios";
}

std::size_t build_fcl_model(FclBv bv, const Mesh& mesh) {
  switch (bv) {
    case FclBv::aabb: return build<fcl::AABBd>(mesh);
    case FclBv::obb: return build<fcl::OBBd>(mesh);
    case FclBv::kdop16: return build<fcl::KDOPd<16>>(mesh);
    case FclBv::kdop18: return build<fcl::KDOPd<18>>(mesh);
    case FclBv::kdop24: return build<fcl::KDOPd<24>>(mesh);
    case FclBv::kios: break;
  }
  return build<fcl::kIOSd>(mesh);
}

}  // namespace cc::bench
