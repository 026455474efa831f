// The bound of apply(), placing a point (rigid_transform.h).
#pragma once

#include "collide/fp.h"
#include "collide/rigid_transform.h"

namespace cc::bounds {

/// apply(t, p): each component within total() of rotation p + translation, for any p with
/// |p|_1 <= p_norm1, assuming only |rotation entries| <= 1 + 2^-48.
struct TransformBound {
  static constexpr double kFactor = 0x1p-50;
  double p_norm1;      // a bound on |p|_1
  double translation;  // max |translation component|
  double rotation_term() const { return kFactor * p_norm1; }
  double translation_term() const { return kFactor * translation; }
  double total() const { return kFactor * (p_norm1 + translation) + fp::subnormal_slack; }
};

}  // namespace cc::bounds
