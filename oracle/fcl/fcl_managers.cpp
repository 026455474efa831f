#include "oracle/fcl/fcl_managers.h"

#include <fcl/broadphase/broadphase_SSaP.h>
#include <fcl/broadphase/broadphase_SaP.h>
#include <fcl/broadphase/broadphase_bruteforce.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree_array.h>
#include <fcl/broadphase/broadphase_interval_tree.h>
#include <fcl/broadphase/broadphase_spatialhash.h>
#include <fcl/broadphase/detail/hierarchy_tree.h>

#include <stdexcept>
#include <string>

namespace cc::fcl_oracle {
namespace {

// SSaP with its three sorted lists in view (they are protected).
class ListedSSaP final : public fcl::SSaPCollisionManagerd {
 public:
  std::string fault() const {
    if (objs_y.size() <= objs_x.size()) return "";
    return "its lists are out of step (" + std::to_string(objs_x.size()) + " objects sorted by x, " +
           std::to_string(objs_y.size()) + " by y, " + std::to_string(objs_z.size()) +
           " by z: unregisterObject missed one after others moved): collide() would read past the end of objs_x";
  }
};

}  // namespace

const std::vector<std::string>& fcl_manager_names() {
  static const std::vector<std::string> names = {"Naive",           "SaP",
                                                 "SSaP",            "IntervalTree",
                                                 "DynamicAABBTree", "DynamicAABBTree_Array",
                                                 "SpatialHashing"};
  return names;
}

std::unique_ptr<fcl::BroadPhaseCollisionManagerd> make_fcl_manager(const std::string& name, const Aabb& world,
                                                                   double cell) {
  if (name == "Naive") return std::make_unique<fcl::NaiveCollisionManagerd>();
  if (name == "SaP") return std::make_unique<fcl::SaPCollisionManagerd>();
  if (name == "SSaP") return std::make_unique<ListedSSaP>();
  if (name == "IntervalTree") return std::make_unique<fcl::IntervalTreeCollisionManagerd>();
  if (name == "DynamicAABBTree") return std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
  if (name == "DynamicAABBTree_Array") return std::make_unique<fcl::DynamicAABBTreeCollisionManager_Arrayd>();
  if (name == "SpatialHashing") {
    using Hash = fcl::SpatialHashingCollisionManagerd<fcl::detail::SimpleHashTable<
        fcl::AABBd, fcl::CollisionObjectd*, fcl::detail::SpatialHash<double>>>;
    return std::make_unique<Hash>(cell, fcl::Vector3d(world.lo.x, world.lo.y, world.lo.z),
                                  fcl::Vector3d(world.hi.x, world.hi.y, world.hi.z));
  }
  throw std::invalid_argument("unknown FCL broad-phase manager \"" + name + "\"");
}

std::string fcl_manager_fault(const fcl::BroadPhaseCollisionManagerd& manager) {
  const auto* ssap = dynamic_cast<const ListedSSaP*>(&manager);
  return ssap != nullptr ? ssap->fault() : "";
}

}  // namespace cc::fcl_oracle
