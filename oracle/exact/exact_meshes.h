// Mesh queries in exact arithmetic: both meshes placed by their poses exactly, every pair of
// triangles whose bounding boxes come near tested by the exact separating-axis test.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "harness/model/input.h"
#include "harness/model/oracle.h"
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/distance_check.h"
#include "oracle/exact/exact_distance.h"

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

/// A triangle placed by a pose in floating point, and a bound on the error of every coordinate.
struct FloatTriangle {
  std::array<Vec3, 3> v;
  double error = 0;
};
FloatTriangle float_triangle(const Triangle& triangle, const RigidTransform& pose);

/// The cheap filter in front of the exact test: true only when exact_sat on the exactly placed
/// triangles certainly finds them apart with a separation (its largest gap over a candidate
/// axis divided by the axis's conditioning, see SatResult) above `threshold` times 1 - 2^-40.
/// judge_meshes skips such pairs, which it would leave unlisted: the verdict is the same. False
/// when unsure (the directions may not span space, the gap is near the threshold, the rounding
/// bounds are too wide).
bool certainly_apart(const FloatTriangle& a, const FloatTriangle& b, double threshold);

/// The distance between the surfaces of the two meshes, each placed exactly by its pose: the
/// least squared distance over their pairs of triangles (exact_distance.h), and a pair that has
/// it (nothing for a mesh without triangles). The pairs are taken in the order of a certified
/// lower bound (the gap between their placed bounding boxes) and those whose bound exceeds the
/// least found are skipped, as are those certainly_apart finds farther than it: every pair's
/// bound is computed, in floating point, and the pairs near the answer in rationals; meshes that
/// meet stop at the first pair that does. Meshes within meshes_outside_domain's domain.
/// At most max_compared pairs are compared in rationals: past them the answer is not complete
/// (and its squared distance and faces the least found so far).
struct ExactMeshDistance {
  Rational squared = 0;
  std::optional<harness::FacePair> faces;
  std::size_t pairs_compared = 0;  // in rationals
  bool complete = true;
};
ExactMeshDistance exact_mesh_distance(const harness::MeshPair& m, std::size_t max_compared = SIZE_MAX);

/// More pairs of triangles than this compared in rationals (each some tenths of a millisecond
/// with placed vertices) and the distance's verdict is undecided instead of slow: the scale, set
/// by a far placement, then dwarfs the meshes, and the rounding of the placement every pair.
inline constexpr std::size_t kMaxDistancePairs = 2000;

/// The verdict on the distance between two placed meshes: outside the
/// domain (meshes_outside_domain) unspecified; else distance_verdict on exact_mesh_distance, each
/// witness checked against its mesh's placed surface.
harness::ExactVerdict judge_mesh_distance(const harness::MeshPair& m);

/// The two triangles of a pair, each placed exactly by its pose.
std::pair<ExactShape, ExactShape> placed_triangles(const harness::MeshPair& m, const harness::FacePair& pair);

}  // namespace cc::exact
