// The exact analysis of a ray against a box, shared by the verdict and the explanation.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/model/input.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

struct RaySlab {
  int axis;
  bool parallel;                 // direction component 0 (or parallel by contract)
  bool origin_inside = true;     // for a parallel slab
  Rational near_t, far_t;        // entry and exit parameters (non-parallel)
  Rational speed;                // |dir[axis]|
};

struct RayAnalysis {
  std::vector<RaySlab> slabs;
  std::optional<Rational> tmin, tmax;  // nothing: -inf, +inf
  std::optional<Rational> enter, exit;
  bool hit = false;
  bool empty_range = false;       // tmin > tmax
  Rational delta;                 // the box growth that makes the ray touch it (<= 0 on a hit)
  std::string binding;            // the condition that needs delta, in words
  std::string flushed;            // direction components parallel by contract
};

/// Requires finite coordinates (check the contract first).
RayAnalysis analyse_ray(const harness::RayAabbInput& in);

}  // namespace cc::exact
