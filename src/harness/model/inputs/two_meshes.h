// The input the kinds on two placed meshes share (every colliding pair; the first one), the same
// for both but for what is asked; their units' shared pieces are src/harness/kinds/two_meshes.h.
#pragma once

#include "harness/model/parts.h"

namespace cc::harness {

/// Mesh a placed by pose_a against mesh b placed by pose_b, asked for every colliding pair of
/// triangles (all_pairs) or for one (first_hit).
template <CollisionMode Mode>
struct TwoMeshesInput {
  static constexpr CollisionMode mode = Mode;
  MeshPair meshes;
  friend bool operator==(const TwoMeshesInput&, const TwoMeshesInput&) = default;
};

/// Its fields: the pair's (a, pose_a, b, pose_b, library) at the top of the case.
template <CollisionMode Mode>
struct Fields<TwoMeshesInput<Mode>> {
  static constexpr auto list = std::tuple{field<&TwoMeshesInput<Mode>::meshes>("")};
};

}  // namespace cc::harness
