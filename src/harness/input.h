// The inputs of one query of each kind. The variant's alternatives follow QueryKind's order.
#pragma once

#include <variant>
#include <vector>

#include "collide/aabb.h"
#include "collide/obb.h"
#include "collide/ray_aabb.h"
#include "collide/sphere.h"
#include "collide/triangle.h"
#include "harness/query_kind.h"

namespace cc::harness {

struct RayAabbInput {
  Ray ray;
  Aabb box;
  friend bool operator==(const RayAabbInput&, const RayAabbInput&) = default;
};
struct SphereSphereInput {
  Sphere a, b;
  friend bool operator==(const SphereSphereInput&, const SphereSphereInput&) = default;
};
struct AabbAabbInput {
  Aabb a, b;
  friend bool operator==(const AabbAabbInput&, const AabbAabbInput&) = default;
};
/// Two point sets, each fitted with a k-DOP; k is one of 6, 14, 16, 18, 24, 26.
struct KdopKdopInput {
  int k = 18;
  std::vector<Vec3> a, b;
  friend bool operator==(const KdopKdopInput&, const KdopKdopInput&) = default;
};
struct ObbObbInput {
  Obb a, b;
  friend bool operator==(const ObbObbInput&, const ObbObbInput&) = default;
};
struct TriAabbInput {
  Triangle tri;
  Aabb box;
  friend bool operator==(const TriAabbInput&, const TriAabbInput&) = default;
};
struct TriObbInput {
  Triangle tri;
  Obb box;
  friend bool operator==(const TriObbInput&, const TriObbInput&) = default;
};
struct TriTriInput {
  Triangle a, b;
  friend bool operator==(const TriTriInput&, const TriTriInput&) = default;
};

using Input = std::variant<RayAabbInput, SphereSphereInput, AabbAabbInput, KdopKdopInput, ObbObbInput, TriAabbInput,
                           TriObbInput, TriTriInput>;

inline QueryKind kind_of(const Input& input) { return static_cast<QueryKind>(input.index()); }

}  // namespace cc::harness
