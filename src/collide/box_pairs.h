// The overlapping pairs of a set of boxes computed from scratch: sort-and-sweep (a full sort
// along one axis every time, the baseline of incremental sweep-and-prune) and brute force.
#pragma once

#include <span>
#include <vector>

#include "collide/sweep_and_prune.h"

namespace cc {

/// The pairs (i, j), i < j, of boxes that share a point (test_aabb_aabb), sorted. Sorts the
/// boxes' endpoints along x (lower before upper at equal values, so touching boxes count) and
/// sweeps them with a list of open intervals, testing y and z for each pair open together:
/// O(n log n + k_x). Boxes with a NaN bound overlap nothing.
std::vector<ObjectPair> sort_and_sweep(std::span<const Aabb> boxes);

/// The same pairs by testing every pair: O(n^2), for checking.
std::vector<ObjectPair> box_pairs_brute_force(std::span<const Aabb> boxes);

}  // namespace cc
