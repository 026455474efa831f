// Mesh queries in exact arithmetic: both meshes placed by their poses exactly, every pair of
// triangles whose bounding boxes come near tested by the exact separating-axis test.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "harness/input.h"
#include "harness/oracle.h"
#include "oracle/exact/convex_sat.h"

namespace cc::exact {

/// Pairs whose bounding boxes are apart by more than this fraction of the scale are not
/// tested; they count as at margin -kNearMargin (ExactVerdict::unlisted_margin). It lies 2^6
/// beyond the widest mesh band (2^-38), so no band judgement depends on an unlisted pair, and
/// it keeps the candidates few when a small mesh is placed far from the origin.
inline constexpr double kNearMargin = 0x1p-32;

/// More candidate pairs than this (the scale, set by a far placement, dwarfs the meshes, so
/// every pair is near contact relative to it) and the verdict is undecided instead of slow.
inline constexpr std::size_t kMaxNearPairs = 200000;

/// Why the meshes or poses lie outside the library's domain (a NaN or infinite value, a pose
/// whose rotation is not orthonormal to within 2^-48 or is a mirror, a magnitude beyond
/// 2^300), or nothing.
std::optional<std::string> meshes_outside_domain(const harness::MeshPair& m);

/// The verdict on all pairs: the exact pair set and the margins of every pair near contact;
/// undecided beyond kMaxNearPairs candidates.
harness::ExactVerdict judge_meshes(const harness::MeshPair& m);

/// The two triangles of a pair, each placed exactly by its pose.
std::pair<ExactShape, ExactShape> placed_triangles(const harness::MeshPair& m, const harness::FacePair& pair);

}  // namespace cc::exact
