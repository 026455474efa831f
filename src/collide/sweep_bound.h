// The bounds of the sweeps' contact times (moving_box.h; widening.h).
#pragma once

#include "collide/moving_box.h"
#include "collide/record_sink.h"
#include "collide/widening.h"

namespace cc::bounds {

/// sweep_obb_obb: a time (+-reach - projection) / rate, two roundings (2.0001u).
inline constexpr Widening kSweepObbTime{"obb time", 4 * fp::u};

/// sweep_aabb_aabb: a time (a.lo - b.hi) / (vb - va), three roundings (3.000001u).
inline constexpr Widening kSweepAabbTime{"aabb time", 8 * fp::u};

}  // namespace cc::bounds

namespace cc {

/// The same as its plain version (moving_box.h), recording its certified quantities into `records`
/// (bound_records.h); the same answer, bit for bit.
SweepHit sweep_aabb_aabb(const Aabb& a, Vec3 va, const Aabb& b, Vec3 vb, bounds::Records& records);

}  // namespace cc
