#include "collide/mesh_contacts.h"

namespace cc {

std::vector<PairContact> mesh_contacts(const Mesh& a, const RigidTransform& pose_a, const Mesh& b,
                                       const RigidTransform& pose_b,
                                       std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs) {
  const RigidTransform t = relative(pose_a, pose_b);
  std::vector<PairContact> contacts;
  contacts.reserve(pairs.size());
  for (const auto& [i, j] : pairs) {
    const Triangle tb = b.triangle(j);
    const Triangle moved{{apply(t, tb.v[0]), apply(t, tb.v[1]), apply(t, tb.v[2])}};
    contacts.push_back({i, j, intersect_triangles(a.triangle(i), moved)});
  }
  return contacts;
}

}  // namespace cc
