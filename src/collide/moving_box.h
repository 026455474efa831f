// Boxes translating with constant velocity over a time step: the dynamic separating-axis test.
#pragma once

#include "collide/aabb.h"
#include "collide/obb.h"

namespace cc {

/// A box translating over a time step: at time t in [0, 1] it is `box` with its centre at
/// box.center + t * velocity (its axes do not turn). Velocity 0 is a box at rest.
struct MovingObb {
  Obb box;
  Vec3 velocity;
  friend constexpr bool operator==(const MovingObb&, const MovingObb&) = default;
};

/// An Aabb as a MovingObb: identity axes, the centre (lo + hi) / 2 rounded, and half extents
/// rounded up where needed so that the Obb contains the Aabb in exact arithmetic (equal to it
/// when nothing rounds). A NaN bound or an inverted box (lo > hi on an axis) gives NaN half
/// extents, and infinite bounds a non-finite centre: sweep_obb_obb reports no hit for either.
MovingObb moving_obb(const Aabb& box, const Vec3& velocity);

/// Whether two moving boxes meet during the step, and when: the first and last times in [0, 1]
/// at which they share a point. On a miss both times are 0.
struct SweepHit {
  bool hit = false;
  double t_first = 0;
  double t_last = 0;
  friend constexpr bool operator==(const SweepHit&, const SweepHit&) = default;
};

/// Whether the closed boxes a and b, each moving as MovingObb says, share a point at some t in
/// the closed interval [0, 1], and the first and last such t. Dynamic separating-axis test on
/// the 15 axes of test_obb_obb, in the same frames, using only the relative velocity
/// v = b.velocity - a.velocity: on each axis the offset of the projected centres moves linearly
/// with t at the rate v . axis, the projections overlap during an interval of times, and the
/// boxes can meet only in the intersection of the 15 intervals with [0, 1]: [t_first, t_last].
///  - Conservative: each axis's interval is widened by a bound on its rounding, the bound of
///    test_obb_obb with |v|_1 added: e = 2^-48 (|d|_1 + |v|_1 + sum of all six half extents)
///    + 6 * 2^-48 (the same sum of half extents) + 2^-1058 on the projections, d = b.center -
///    a.center, and 2^-51 of their magnitude on the solved times. So boxes that meet in exact
///    arithmetic at some t in [0, 1] are always a hit, t_first <= the exact first contact time
///    and t_last >= the exact last one.
///  - Tolerance: at t_first and at t_last the boxes are apart on none of the 15 axes by more
///    than 2^-40 M, where M is the largest absolute coordinate of the centres, the velocities and
///    the half extents (gaps measured along the axes as given, a_i x b_j not normalised). So
///    t_first is early, and a hit may be reported for boxes that never meet, by at most the time
///    the boxes take to close that gap along the axis that decides.
///  - Touching counts: boxes touching at t = 0 or at t = 1, or grazing in between, are a hit.
///    Boxes touching or overlapping at t = 0 give t_first = 0.
///  - Rate 0: an axis whose rate is exactly 0 as computed is decided for the whole step by
///    test_obb_obb's criterion (with the bound above). Zero relative velocity: a hit exactly
///    when test_obb_obb(a.box, b.box), with t_first = 0 and t_last = 1.
///  - Nearly parallel edges: as in test_obb_obb; the gap, the radii and the rate on their
///    cross product are all nearly zero, the bound keeps that axis's interval covering the
///    step, and the face axes decide. No epsilon is added to the rotation entries.
///  - Symmetric: swapping a and b gives the same answer bit for bit.
///  - Domain: finite inputs with every centre, velocity and half-extent coordinate of magnitude
///    at most 2^500, half extents >= 0, axes orthonormal to within kObbOrthonormalTolerance.
///    NaN or infinite input, or a negative half extent: no hit. Axes further from orthonormal:
///    the answer is that of the same arithmetic, unchecked.
SweepHit sweep_obb_obb(const MovingObb& a, const MovingObb& b);

/// The same for axis-aligned boxes a and b moving with velocities va and vb: on each coordinate
/// axis the times at which [a.lo + t va, a.hi + t va] and [b.lo + t vb, b.hi + t vb] overlap,
/// intersected with each other and with [0, 1].
///  - Exact where possible: an axis with va == vb (rate exactly 0) is decided by
///    test_aabb_aabb's comparisons, exactly; a time (a.lo - b.hi) / (vb - va) or
///    (a.hi - b.lo) / (vb - va) whose two differences and quotient are exact in floating point
///    is reported as it is. Zero relative velocity: a hit exactly when test_aabb_aabb(a, b),
///    with t_first = 0 and t_last = 1.
///  - Otherwise conservative: a rounded time (at most three roundings) is moved outward by 2^-50
///    of its magnitude plus 2^-1058. Boxes that meet in exact arithmetic at some t in [0, 1] are
///    always a hit; t_first <= the exact first contact time and t_last >= the exact last one,
///    each off by less than 2^-49; a hit may be reported for boxes whose per-axis intervals miss
///    each other by less than 2^-48.
///  - Touching at t = 0 or at t = 1 counts. Boxes touching or overlapping at t = 0 give
///    t_first = 0. Zero-extent boxes take part as the rectangles, segments or points they are.
///  - Symmetric: swapping (a, va) and (b, vb) gives the same answer bit for bit.
///  - Domain: finite inputs of magnitude at most 2^1000. NaN or an infinite bound or velocity
///    component, or an inverted box (lo > hi on an axis): no hit.
SweepHit sweep_aabb_aabb(const Aabb& a, Vec3 va, const Aabb& b, Vec3 vb);

}  // namespace cc
