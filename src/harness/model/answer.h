// What a party says about one query.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cc::harness {

/// A pair of triangles of two meshes: (face of a, face of b).
using FacePair = std::pair<std::uint32_t, std::uint32_t>;

/// The answer to a query: whether the shapes meet, and for some queries parameters of the
/// contact. ray_aabb: {t_enter, t_exit} when hit. Mesh queries: the colliding pairs, sorted
/// (mesh_mesh_first: the one pair found). ray_mesh: {t} and the pair (face, 0) when hit.
/// moving_obb: {t_first, t_last} when hit. broadphase: the overlapping pairs of boxes of each
/// frame, sorted, in `frames`; hit when some frame has one.
struct Answer {
  bool hit = false;
  std::vector<double> params;
  std::vector<FacePair> pairs;
  std::vector<std::vector<FacePair>> frames;
  friend bool operator==(const Answer&, const Answer&) = default;
};

/// The answer of one second-opinion party (FCL or libccd) to one query.
struct Opinion {
  enum class Status { answered, not_applicable, failed };
  std::string party;  // e.g. "fcl.OBBd::overlap"
  Status status = Status::not_applicable;
  Answer answer;
  std::string detail;  // why not applicable, or what failed
};

}  // namespace cc::harness
