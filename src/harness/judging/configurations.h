// The named configurations the generators are meant to make, per query kind, each recognised
// from a case's inputs and its exact verdict (not from how the case was built): touching and
// nearly touching either way, parallel and nearly parallel frames, edges or rays, flat, segment
// and point shapes, shapes far from the origin compared with their size, aspect ratios past
// 2^20, frames at the orthonormality tolerance, rays from far away or with negative parameters,
// and so on. A property counts them over its cases and fails if one never appears: a generator
// that silently stops making a configuration is caught.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::harness {

/// The configurations of expected_configurations(kind) that the case is in.
std::vector<std::string_view> configurations_of(const Input& input, const ExactVerdict& exact);

/// Every configuration the generators of a kind are meant to make.
std::span<const std::string_view> expected_configurations(QueryKind kind);

}  // namespace cc::harness
