#include "oracle/fcl/fcl_oracle.h"

#include <exception>
#include <stdexcept>

#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

using harness::QueryKind;

// Runs one adapter; an exception from FCL or libccd becomes a failed opinion.
template <class Adapter, class In>
Opinion guarded(const std::string& party, Adapter adapter, const In& in) {
  try {
    return adapter(in);
  } catch (const std::exception& e) {
    return failed(party, std::string("exception: ") + e.what());
  } catch (...) {
    return failed(party, "exception of unknown type");
  }
}

struct Ask {
  std::vector<Opinion> operator()(const harness::RayAabbInput& in) const {
    return {guarded("libccd.GJK", ccd_gjk_segment_box, in), guarded("libccd.MPR", ccd_mpr_segment_box, in)};
  }
  std::vector<Opinion> operator()(const harness::SphereSphereInput& in) const {
    return {guarded("fcl.collide(Sphere,Sphere)", fcl_collide_spheres, in)};
  }
  std::vector<Opinion> operator()(const harness::AabbAabbInput& in) const {
    return {guarded("fcl.AABBd::overlap", fcl_aabb_overlap, in)};
  }
  std::vector<Opinion> operator()(const harness::KdopKdopInput& in) const {
    return {guarded("fcl.KDOPd<k>::overlap", fcl_kdop_overlap, in)};
  }
  std::vector<Opinion> operator()(const harness::ObbObbInput& in) const {
    return {guarded("fcl.OBBd::overlap", fcl_obb_overlap, in), guarded("fcl.collide(Box,Box)", fcl_collide_boxes, in)};
  }
  std::vector<Opinion> operator()(const harness::TriAabbInput& in) const {
    return {guarded("fcl.shapeTriangleIntersect", [](const auto& x) { return fcl_shape_triangle(x); }, in)};
  }
  std::vector<Opinion> operator()(const harness::TriObbInput& in) const {
    return {guarded("fcl.shapeTriangleIntersect", [](const auto& x) { return fcl_shape_triangle(x); }, in)};
  }
  std::vector<Opinion> operator()(const harness::TriTriInput& in) const {
    return {guarded("fcl.Intersect::intersect_Triangle", fcl_intersect_triangle, in)};
  }
  std::vector<Opinion> operator()(const harness::MeshMeshInput& in) const { return meshes(in.meshes, false); }
  std::vector<Opinion> operator()(const harness::MeshMeshFirstInput& in) const { return meshes(in.meshes, true); }
  static std::vector<Opinion> meshes(const harness::MeshPair& m, bool first_only) {
    std::vector<Opinion> out;
    for (const std::string& party : fcl_mesh_parties()) {
      out.push_back(guarded(party, [&](const harness::MeshPair& x) { return fcl_collide_meshes(party, x, first_only); }, m));
    }
    return out;
  }
};

}  // namespace

FclSecondOpinion::FclSecondOpinion() {
  if (!fcl_supports_used_pairs()) {
    throw std::runtime_error("FCL's collision matrix lacks sphere-sphere or box-box: its answers would read as misses");
  }
}

std::vector<Opinion> FclSecondOpinion::opinions(const harness::Input& input) const { return std::visit(Ask{}, input); }

std::vector<std::string> FclSecondOpinion::parties(QueryKind kind) const {
  switch (kind) {
    case QueryKind::ray_aabb: return {"libccd.GJK", "libccd.MPR"};
    case QueryKind::sphere_sphere: return {"fcl.collide(Sphere,Sphere)"};
    case QueryKind::aabb_aabb: return {"fcl.AABBd::overlap"};
    case QueryKind::kdop_kdop: return {"fcl.KDOPd<k>::overlap"};
    case QueryKind::obb_obb: return {"fcl.OBBd::overlap", "fcl.collide(Box,Box)"};
    case QueryKind::tri_aabb:
    case QueryKind::tri_obb: return {"fcl.shapeTriangleIntersect"};
    case QueryKind::tri_tri: return {"fcl.Intersect::intersect_Triangle"};
    case QueryKind::mesh_mesh:
    case QueryKind::mesh_mesh_first: return fcl_mesh_parties();
  }
  return {};
}

}  // namespace cc::fcl_oracle
