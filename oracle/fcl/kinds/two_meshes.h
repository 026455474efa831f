// The second opinions on two placed meshes: FCL's BVHModel collision
// with each of six volume types, each party's name and band with its call.
#pragma once

#include <vector>

#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

/// One BVHModel party: its name, band and volume type, and whether it is asked only of cases
/// whose library hierarchy is a sphere tree.
struct ModelParty {
  std::string name;
  Band band;
  Volume volume;
  bool sphere_trees_only = false;
};

/// The six BVHModel parties of the mesh kinds.
inline const std::vector<ModelParty>& model_parties() {
  static const std::string moved =
      "both meshes moved into the world frame in floating point and refitted, then intersect_Triangle (2^-40)";
  static const std::vector<ModelParty> parties = {
      {"fcl.BVHModel<OBBd>",
       {0x1p-38, BandSides::two_sided, 0,
        "leaves by intersect_Triangle (2^-40) on triangles moved by FCL's relative transform; the OBB tests "
        "only prune (|R_ij| + 1e-6)"},
       Volume::obb},
      {"fcl.BVHModel<OBBRSSd>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<OBBd>"}, Volume::obbrss},
      {"fcl.BVHModel<AABBd>", {0x1p-38, BandSides::two_sided, 0, moved}, Volume::aabb},
      {"fcl.BVHModel<KDOPd<18>>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<AABBd>"}, Volume::kdop18},
      // The sphere-based models, second opinions for the library's sphere trees (FCL has no tree
      // of plain spheres), asked of those cases only: kIOS (up to five spheres and an OBB per
      // node) and RSS (rectangle swept spheres); their traversal moves the triangles and tests
      // the leaves as the OBB models' does.
      {"fcl.BVHModel<kIOSd>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<OBBd>"}, Volume::kios, true},
      {"fcl.BVHModel<RSSd>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<OBBd>"}, Volume::rss, true}};
  return parties;
}

/// The BVHModel parties on inputs of type In (which hold `meshes`), asking for every contact or
/// only the first.
template <class In>
std::vector<Party<In>> bvh_model_parties(bool first_only) {
  std::vector<Party<In>> out;
  for (const ModelParty& p : model_parties()) {
    out.push_back({p.name, p.band, [volume = p.volume, spheres = p.sphere_trees_only, first_only](const In& in) {
                     if (spheres && in.meshes.library.bv != harness::BvType::sphere) {
                       return not_applicable("asked of sphere trees only");
                     }
                     return fcl_collide_models(volume, in.meshes, first_only);
                   }});
  }
  return out;
}

}  // namespace cc::fcl_oracle
