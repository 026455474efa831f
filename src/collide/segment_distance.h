// The distance between two segments, with witness points (separation.h).
#pragma once

#include <utility>

#include "collide/segment.h"
#include "collide/separation.h"

namespace cc {

/// The distance between two closed segments (never negative: segments have no inside) and a
/// closest pair, on_a on a and on_b on b. Parallel segments: any closest pair. A point segment
/// (a == b) is a point.
///  - The bound is certified after the fact: the witnesses give an upper bound on the distance
///    (they are points of the segments), the gap between the segments' projections on the
///    witnesses' direction a lower bound (as for any direction); distance_error covers both
///    ends, so it is small where the witnesses are nearly closest, whatever the configuration.
///  - Domain: finite inputs of magnitude at most 2^500; outside it, NaN (separation.h).
///    point_error: 16u of the largest endpoint coordinate, plus the subnormal slack.
Separation distance_segment_segment(const Segment& a, const Segment& b);

/// The parameters (s on a, t on b, both in [0, 1]) of a nearly closest pair a.a + s (a.b - a.a),
/// b.a + t (b.b - b.a): the minimiser of their distance as computed in floating point. Parallel
/// segments: some pair on the flat part of the distance. A point segment takes 0. Nothing is
/// certified: distance_segment_segment certifies the pair it takes from here.
std::pair<double, double> closest_segment_parameters(const Segment& a, const Segment& b);

/// A certified lower bound on the distance between a and b from one direction: the gap between
/// their projections on it (b's least minus a's greatest) over its length, less its rounding
/// bound, and 0 where the projections overlap. Exact in the limit along the direction of a
/// closest pair; any other direction gives less. A zero or non-finite direction gives 0.
double segment_gap_along(const Segment& a, const Segment& b, const Vec3& direction);

}  // namespace cc
