// Bounding spheres: a ball around points, and a ball around two balls, each holding what it
// bounds in exact arithmetic (the hierarchies' sphere volumes and their building heuristics).
#pragma once

#include <span>

#include "collide/sphere.h"

namespace cc {

/// A double at least the exact distance |p - q| (the coordinates as the rationals they are):
/// computed on the difference scaled by a power of two, then rounded up by 2^-48 of itself (and
/// by the subnormal slack when it is that small). 0 only when p == q. Finite inputs of magnitude
/// at most 2^1000 (the difference neither overflows nor underflows once scaled).
double distance_upper_bound(const Vec3& p, const Vec3& q);

/// A ball that holds every point in exact arithmetic: Ritter's ball (the diameter between a
/// point far from the first one and the point farthest from it, grown by each point outside it
/// until it takes that point), its radius then the largest distance_upper_bound from its centre
/// to a point. Near-minimal (Ritter's ball is a few percent to a few tens of percent wider than
/// the smallest). One point gives radius 0; coincident points too. Points must be finite, of
/// magnitude at most 2^500 (so that the centre's heuristic squares do not overflow), and not
/// empty.
Sphere fit_sphere(std::span<const Vec3> points);

/// A ball that holds both balls in exact arithmetic: the one that holds the other when it does
/// (by distance_upper_bound of the centres), else the ball whose diameter spans both along the
/// line of their centres, its radius certified by the distances from its centre. Finite inputs
/// of magnitude at most 2^500, radii >= 0.
Sphere merge_spheres(const Sphere& a, const Sphere& b);

}  // namespace cc
