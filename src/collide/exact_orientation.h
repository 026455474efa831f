// Exact orientation signs: the sign of the 3x3 determinant of three edge vectors (which side of
// a plane a point lies on) and of its 2x2 projections, exact for every finite input. A floating-
// point evaluation decides when it exceeds a bound on its own rounding error; otherwise the
// determinant is evaluated again in integers wide enough for any finite doubles.
#pragma once

#include <optional>

#include "collide/vec3.h"

namespace cc {

/// The exact sign of det[b - a; c - a; d - a] = (d - a) . ((b - a) x (c - a)) for the points as
/// given (coordinates taken as exact reals, nothing rounded): +1 when d lies on the side of the
/// plane through a, b, c that (b - a) x (c - a) points to, -1 on the other side, 0 when the four
/// are coplanar (also when a, b, c are collinear or any two points coincide). Swapping two points
/// negates it; translating all four by the same vector (exactly) keeps it.
/// std::nullopt exactly when a coordinate of a point is NaN or infinite: every finite input is
/// decided, whatever the spread of its exponents (subnormals included).
std::optional<int> orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The exact sign of the 2-D determinant (b - a) x (c - a) of the points projected by dropping
/// coordinate `drop` (0: x, 1: y, 2: z): for drop = 2, (b.x-a.x)(c.y-a.y) - (b.y-a.y)(c.x-a.x);
/// for drop = 0 the same on (y, z); for drop = 1 on (z, x). So drop = i gives the sign of component
/// i of the cross product (b - a) x (c - a). 0 when the projected points are collinear or two of
/// them coincide. std::nullopt exactly when one of the two kept coordinates of a, b or c is NaN or
/// infinite (the dropped one is not read), or drop is not 0, 1 or 2.
std::optional<int> planar_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, int drop);

/// The two stages of the functions above, each alone, for tests and measurements.
namespace orientation_stages {

/// The sign of the floating-point determinant when it exceeds its rounding-error bound (then it is
/// the exact sign); std::nullopt when it does not (also for non-finite inputs and overflow).
std::optional<int> filtered_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
std::optional<int> filtered_planar_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, int drop);

/// The sign evaluated in integer arithmetic, without the filter (same results and std::nullopt
/// rule as orientation_sign and planar_orientation_sign).
std::optional<int> exact_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
std::optional<int> exact_planar_orientation_sign(const Vec3& a, const Vec3& b, const Vec3& c, int drop);

}  // namespace orientation_stages

}  // namespace cc
