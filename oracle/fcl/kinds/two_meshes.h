// The second opinions on two placed meshes: FCL's BVHModel collision
// with each of six volume types, each party's name and band with its call.
#pragma once

#include <vector>

#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

/// The six BVHModel parties on inputs of type In (which hold `meshes`), asking for every
/// contact or only the first.
template <class In>
std::vector<Party<In>> bvh_model_parties(bool first_only) {
  const auto party = [first_only](Volume volume) {
    return [volume, first_only](const In& in) { return fcl_collide_models(volume, in.meshes, first_only); };
  };
  const std::string_view moved =
      "both meshes moved into the world frame in floating point and refitted, then intersect_Triangle (2^-40)";
  return {{"fcl.BVHModel<OBBd>",
           {0x1p-38, BandSides::two_sided, 0,
            "leaves by intersect_Triangle (2^-40) on triangles moved by FCL's relative transform; the OBB tests "
            "only prune (|R_ij| + 1e-6)"},
           party(Volume::obb)},
          {"fcl.BVHModel<OBBRSSd>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<OBBd>"}, party(Volume::obbrss)},
          {"fcl.BVHModel<AABBd>", {0x1p-38, BandSides::two_sided, 0, moved}, party(Volume::aabb)},
          {"fcl.BVHModel<KDOPd<18>>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<AABBd>"}, party(Volume::kdop18)},
          // The sphere-based models, second opinions for the library's sphere trees (FCL has no
          // tree of plain spheres): kIOS (up to five spheres and an OBB per node) and RSS
          // (rectangle swept spheres); their traversal moves the triangles and tests the leaves
          // as the OBB models' does.
          {"fcl.BVHModel<kIOSd>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<OBBd>"}, party(Volume::kios)},
          {"fcl.BVHModel<RSSd>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<OBBd>"}, party(Volume::rss)}};
}

}  // namespace cc::fcl_oracle
