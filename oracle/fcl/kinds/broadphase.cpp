// broadphase's second opinions: every FCL manager given the boxes as its objects' AABBs, frame by frame
// (registered when a box appears, unregistered when it goes, update() every frame), asked for the
// overlapping pairs with a callback that only records them. setup() after the first frame,
// update() after every later one.
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "oracle/fcl/fcl_managers.h"
#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

namespace cc::fcl_oracle {
namespace {

constexpr double kBroadphaseTimeLimit = 0.05;  // seconds of CPU time per manager and case

// A collision object whose AABB is given, not computed from its geometry: the managers read
// getAABB() and never recompute it.
class BoxObject final : public fcl::CollisionObjectd {
 public:
  BoxObject(const std::shared_ptr<fcl::CollisionGeometryd>& geometry, std::size_t slot) : fcl::CollisionObjectd(geometry) {
    setUserData(reinterpret_cast<void*>(slot));
  }
  void set_box(const Aabb& box) {
    aabb.min_ = fcl::Vector3d(box.lo.x, box.lo.y, box.lo.z);
    aabb.max_ = fcl::Vector3d(box.hi.x, box.hi.y, box.hi.z);
  }
  std::size_t slot() const { return reinterpret_cast<std::size_t>(getUserData()); }
};

bool record_pair(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
  auto* pairs = static_cast<std::vector<harness::FacePair>*>(data);
  const auto i = static_cast<std::uint32_t>(static_cast<BoxObject*>(a)->slot());
  const auto j = static_cast<std::uint32_t>(static_cast<BoxObject*>(b)->slot());
  pairs->push_back(std::minmax(i, j));
  return false;  // go on
}

// The finite hull of every box (for SpatialHashing's grid) and a cell of about the boxes' size.
std::pair<Aabb, double> world_of(const harness::BroadphaseInput& in) {
  Aabb world{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  double largest = 0;
  for (const auto& frame : in.frames) {
    for (const auto& box : frame) {
      if (!box) continue;
      for (int k = 0; k < 3; ++k) {
        if (std::isfinite(box->lo[k])) world.lo[k] = std::min(world.lo[k], box->lo[k]);
        if (std::isfinite(box->hi[k])) world.hi[k] = std::max(world.hi[k], box->hi[k]);
        const double extent = box->hi[k] - box->lo[k];
        if (std::isfinite(extent)) largest = std::max(largest, extent);
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    if (!(world.lo[k] < world.hi[k])) world.lo[k] = -1, world.hi[k] = 1;
  }
  return {world, largest > 0 ? largest : 1.0};
}

// FCL's class name for a manager: "SaP" -> "fcl.SaPCollisionManager".
std::string party_of(const std::string& manager) {
  return manager == "DynamicAABBTree_Array" ? "fcl.DynamicAABBTreeCollisionManager_Array"
                                            : "fcl." + manager + "CollisionManager";
}

Opinion run_manager(const std::string& manager, const harness::BroadphaseInput& in) {
  for (const auto& frame : in.frames) {
    for (const auto& box : frame) {
      for (int k = 0; box && k < 3; ++k) {
        // FCL's managers assume lo <= hi (SaP's update crashes on an inverted box).
        if (!(box->lo[k] <= box->hi[k])) return not_applicable("a box with lo > hi or NaN");
        // FCL 0.7's SaP crashes (SIGSEGV in SaPCollisionManager::update_) when a box flat on an
        // axis moves, e.g. one segment box over two frames (a case in corpora/broadphase).
        if (manager == "SaP" && box->lo[k] == box->hi[k] && in.frames.size() > 1) {
          return not_applicable("a box of zero extent moves: SaP's update crashes on it");
        }
      }
    }
  }
  const auto [world, cell] = world_of(in);
  const auto fcl_manager = make_fcl_manager(manager, world, cell);
  const auto geometry = std::make_shared<fcl::Boxd>(1, 1, 1);
  std::vector<std::unique_ptr<BoxObject>> objects;
  // An object that leaves stays alive to the end of the case: a manager that keeps a stale
  // pointer to it after unregisterObject (IntervalTree and SSaP do) then reads the object that
  // left, not whatever the allocator put there since, so its answer is the same in every process.
  std::vector<std::unique_ptr<BoxObject>> left;
  Opinion o = answered(false);
  for (const auto& frame : in.frames) {
    objects.resize(std::max(objects.size(), frame.size()));
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (frame[i] && !objects[i]) {
        objects[i] = std::make_unique<BoxObject>(geometry, i);
        objects[i]->set_box(*frame[i]);
        fcl_manager->registerObject(objects[i].get());
      } else if (frame[i]) {
        objects[i]->set_box(*frame[i]);
      } else if (objects[i]) {
        fcl_manager->unregisterObject(objects[i].get());
        left.push_back(std::move(objects[i]));
      }
    }
    if (&frame == &in.frames.front()) {
      fcl_manager->setup();  // as FCL's own tests do after the first registration
    } else {
      fcl_manager->update();
    }
    if (const std::string fault = fcl_manager_fault(*fcl_manager); !fault.empty()) {
      return failed("frame " + std::to_string(&frame - in.frames.data()) + ": " + fault);
    }
    std::vector<harness::FacePair> pairs;
    fcl_manager->collide(&pairs, record_pair);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    o.answer.hit |= !pairs.empty();
    o.answer.frames.push_back(std::move(pairs));
  }
  return o;
}

Opinion fcl_broadphase(const std::string& manager, const harness::BroadphaseInput& in) {
  // IntervalTree's unregisterObject can loop for ever in deleteNode (about 3% of the campaign's
  // cases): every manager runs under a time limit, and what it leaves behind is leaked. A
  // manager that returns takes at most 8 ms of CPU time on the generated cases (the slowest,
  // SpatialHashing, over 4000 of them); the limit is 6 times that, since every call cut short
  // costs the whole limit.
  Opinion o;
  if (!run_with_time_limit(kBroadphaseTimeLimit, [&] { o = run_manager(manager, in); })) {
    return timed_out("did not return within 50 ms of CPU time");
  }
  return o;
}

}  // namespace

template <>
const std::vector<Party<harness::BroadphaseInput>>& fcl_parties() {
  static const std::vector<Party<harness::BroadphaseInput>> parties = [] {
    // Every manager is given the boxes as the objects' AABBs and reports the pairs it finds overlapping.
    constexpr Band kManagerBand{0, BandSides::exact, 0, "AABB::overlap on the given bounds (closed boxes): exact"};
    std::vector<Party<harness::BroadphaseInput>> out;
    for (const std::string& manager : fcl_manager_names()) {
      out.push_back({party_of(manager), kManagerBand,
                     [manager](const harness::BroadphaseInput& in) { return fcl_broadphase(manager, in); }});
    }
    return out;
  }();
  return parties;
}

}  // namespace cc::fcl_oracle
