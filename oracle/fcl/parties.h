// The individual FCL and libccd adapters (internal to oracle/fcl).
#pragma once

#include "harness/model/input.h"
#include "harness/model/answer.h"

namespace cc::fcl_oracle {

using harness::Opinion;

// libccd, segment vs box.
Opinion ccd_gjk_segment_box(const harness::RayAabbInput& in);
Opinion ccd_mpr_segment_box(const harness::RayAabbInput& in);

// FCL bounding volumes.
Opinion fcl_aabb_overlap(const harness::AabbAabbInput& in);
Opinion fcl_obb_overlap(const harness::ObbObbInput& in);
Opinion fcl_kdop_overlap(const harness::KdopKdopInput& in);

// FCL shapes and primitives.
Opinion fcl_collide_spheres(const harness::SphereSphereInput& in);
Opinion fcl_collide_boxes(const harness::ObbObbInput& in);
Opinion fcl_shape_triangle(const harness::TriAabbInput& in);
Opinion fcl_shape_triangle(const harness::TriObbInput& in);
Opinion fcl_intersect_triangle(const harness::TriTriInput& in);

// FCL's BVHModel collision on meshes: one party per volume type, answering with pairs.
std::vector<std::string> fcl_mesh_parties();
Opinion fcl_collide_meshes(const std::string& party, const harness::MeshPair& m, bool first_only);

// FCL's broadphase managers, each over the boxes of every frame.
std::vector<std::string> fcl_broadphase_parties();
Opinion fcl_broadphase(const std::string& manager, const harness::BroadphaseInput& in);
// FCL's continuousCollide (conservative advancement, translation) on two moving boxes.
Opinion fcl_continuous_collide(const harness::MovingObbInput& in);
/// True when FCL's collision matrix (libccd solver) has the shape pairs used above.
bool fcl_supports_used_pairs();

/// An opinion that answered.
inline Opinion answered(std::string party, bool hit) {
  Opinion o;
  o.party = std::move(party);
  o.status = Opinion::Status::answered;
  o.answer.hit = hit;
  return o;
}

/// An opinion that failed: an exception, or a call that did not return in time.
inline Opinion failed(std::string party, std::string what) {
  Opinion o;
  o.party = std::move(party);
  o.status = Opinion::Status::failed;
  o.detail = std::move(what);
  return o;
}

/// An opinion that does not apply to this input.
inline Opinion not_applicable(std::string party, std::string why) {
  Opinion o;
  o.party = std::move(party);
  o.status = Opinion::Status::not_applicable;
  o.detail = std::move(why);
  return o;
}

}  // namespace cc::fcl_oracle
