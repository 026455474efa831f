// The foot of a point on a triangle: the point of the triangle nearest it, when that lies inside.
#pragma once

#include "collide/triangle.h"

namespace cc {

/// The point of t nearest p when that is p's foot on t's plane, as t.v[0] + s e1 + t e2 with the
/// coordinates s, t >= 0, s + t <= 1 as computed: a point of t, within 32u of its largest vertex
/// coordinate (triangle_distance_bound.h), however thin or small t is; an ill-conditioned plane
/// only moves it within t, away from the foot. The coordinates come from e1, e2 and p - t.v[0]
/// scaled by one power of two (their products of four neither overflow nor, for the largest,
/// underflow), by cross products: with n = e1 x e2 and f the foot less v0, s = (f x e2).n / n.n,
/// t = (e1 x f).n / n.n. False when the foot lies outside t, t is degenerate as computed, or an
/// input is NaN.
bool foot_in_triangle(const Vec3& p, const Triangle& t, Vec3& foot);

}  // namespace cc
