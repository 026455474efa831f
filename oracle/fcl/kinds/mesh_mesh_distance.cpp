// mesh_mesh_distance's second opinions: FCL's distance() with nearest points on BVHModel<RSSd>
// and <OBBRSSd>, the volumes FCL builds for distance (fcl_meshes.cpp). Its traversal computes
// TriangleDistance::triDistance on b's triangles moved into a's frame: floating point with no
// tolerance, rounding only; where it gives 0 its points are arbitrary (triDistance's header), so
// it is judged on the hit alone there.
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

constexpr Band kMeshDistanceBand{0x1p-40, BandSides::two_sided, 0x1p-40,
                                 "b's triangles moved into a's frame and triangle distances in floating point with no "
                                 "tolerance: rounding only"};

Opinion mesh_distance(Volume volume, const harness::MeshMeshDistanceInput& in) {
  if (in.meshes.a.mesh->size() == 0 || in.meshes.b.mesh->size() == 0) return not_applicable("a mesh without triangles");
  const FclMeshDistance d = fcl_mesh_distance(volume, in.meshes);
  if (d.distance == 0) return answered(true);
  harness::Answer answer = harness::Answer::of(d.distance < 0);
  answer.params = {d.distance, d.on_a.x, d.on_a.y, d.on_a.z, d.on_b.x, d.on_b.y, d.on_b.z};
  return answered(answer);
}

}  // namespace

template <>
const std::vector<Party<harness::MeshMeshDistanceInput>>& fcl_parties() {
  static const std::vector<Party<harness::MeshMeshDistanceInput>> parties = {
      {"fcl.BVHModel<RSSd>::distance", kMeshDistanceBand,
       [](const harness::MeshMeshDistanceInput& in) { return mesh_distance(Volume::rss, in); }},
      {"fcl.BVHModel<OBBRSSd>::distance", kMeshDistanceBand,
       [](const harness::MeshMeshDistanceInput& in) { return mesh_distance(Volume::obbrss, in); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
