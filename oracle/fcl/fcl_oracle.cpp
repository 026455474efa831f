#include "oracle/fcl/fcl_oracle.h"

#include <exception>
#include <stdexcept>

#include "oracle/fcl/fcl_managers.h"
#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

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
  std::vector<Opinion> operator()(const harness::BroadphaseInput& in) const {
    std::vector<Opinion> out;
    const std::vector<std::string> parties = fcl_broadphase_parties();
    for (std::size_t i = 0; i < parties.size(); ++i) {
      const std::string& manager = fcl_manager_names()[i];
      out.push_back(guarded(parties[i], [&](const harness::BroadphaseInput& x) { return fcl_broadphase(manager, x); }, in));
    }
    return out;
  }
  std::vector<Opinion> operator()(const harness::RayMeshInput&) const { return {}; }  // FCL 0.7 casts no rays
  std::vector<Opinion> operator()(const harness::MovingObbInput& in) const {
    return {guarded("fcl.continuousCollide", fcl_continuous_collide, in)};
  }
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
    case QueryKind::broadphase: return fcl_broadphase_parties();
    case QueryKind::ray_mesh: return {};
    case QueryKind::moving_obb: return {"fcl.continuousCollide"};
  }
  return {};
}

int FclSecondOpinion::abandoned_calls() const { return fcl_oracle::abandoned_calls(); }

}  // namespace cc::fcl_oracle
