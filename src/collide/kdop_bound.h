// The bound of fit_kdop's projections (kdop.h), and its record.
#pragma once

#include "collide/fp.h"
#include "collide/kdop.h"
#include "collide/record_sink.h"

namespace cc::bounds {

/// A projection onto a 2- or 3-term direction, s = the sum of the exact products t_i, is within
/// 2u sum |t_i| of its value; s -+ kKdopProjection sum |t_i| also covers the rounding of the
/// widened bounds.
inline constexpr double kKdopProjection = 4 * fp::u;

/// The projection s of a point onto a 2- or 3-term direction, and its pad.
struct KdopProjection {
  KdopDirection direction;
  Vec3 point;
  double s, pad;
};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (kdop.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points, bounds::Records& records);

}  // namespace cc
