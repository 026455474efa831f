// Bullet's GJK (btGjkPairDetector, with the EPA penetration solver as Bullet's collision
// algorithms pair them, and btGjkEpaSolver2's signed distance of a ball) on convex shapes, for the
// kinds of convex shapes (internal to oracle/bullet).
#pragma once

#include <BulletCollision/CollisionShapes/btConvexShape.h>
#include <LinearMath/btTransform.h>

#include <optional>

#include "collide/triangle.h"
#include "collide/vec3.h"
#include "harness/model/party.h"

namespace cc::bullet_oracle {

/// What GJK (with EPA for penetration) reports between two placed convex shapes: the distance
/// (< 0 overlapping), its point on b, and the point on a it gives with it (the point on b plus
/// the distance along its normal).
struct GjkClosest {
  double distance = 0;
  Vec3 on_a, on_b;
};

/// GJK's report on two placed convex shapes, or nothing when it reports none.
std::optional<GjkClosest> gjk_closest(const btConvexShape& a, const btTransform& place_a, const btConvexShape& b,
                                      const btTransform& place_b);

/// GJK's report as a distance kind's answer: the signed distance and both points (a hit where it is
/// <= 0), or a failure where it reports none.
harness::Opinion distance_answer(const std::optional<GjkClosest>& closest);

/// btGjkEpaSolver2's signed distance from a ball (its centre and radius) to a placed convex shape,
/// as a distance kind's answer: GJK on the shape without its margin and the centre, the margins
/// and the radius subtracted; EPA with margins where they overlap. The distance alone (a hit where
/// it is <= 0): the witnesses it gives apart are the shape's point moved by the margins toward the
/// centre, and the centre, on neither surface. A failure where it reports none (infinity).
harness::Opinion epa_signed_distance(const Vec3& center, double radius, const btConvexShape& shape,
                                     const btTransform& place);

/// Its band: GJK's and EPA's accuracies in double precision (1e-12, on the distance, relative or
/// absolute) with room for the rounding of the support points: at unit scale, 2^-36.
inline constexpr harness::Band kEpaBand{0x1p-36, harness::BandSides::two_sided, 0x1p-36,
                                         "GJK's and EPA's accuracies in double precision (1e-12): the band they mean at unit scale"};

/// Its distance alone.
std::optional<double> gjk_distance(const btConvexShape& a, const btTransform& place_a, const btConvexShape& b,
                                   const btTransform& place_b);

/// A hit when GJK reports a distance <= 0 between the triangle (a btTriangleShape) and the box
/// (a btBoxShape of these half extents placed by axes and centre), both with collision margin 0.
harness::Opinion gjk_triangle_box(const Triangle& tri, const Vec3& half, const Mat3& axes, const Vec3& center);

/// Its band for a distance and its points: the same tolerances, and its relative one on the
/// squared distance (1e-6).
inline constexpr harness::Band kGjkDistanceBand{
    0x1p-9, harness::BandSides::two_sided, 0x1p-9,
    "GJK's absolute tolerances (about 1e-3) and its relative one on the squared distance (1e-6): the band they mean at unit scale"};

/// Its band: GJK's and EPA's tolerances are absolute (a separating axis shorter than 1e-3, a
/// distance within 1e-3 of 0 with a degenerate simplex, go to the penetration solver): at unit
/// scale, 2^-9.
inline constexpr harness::Band kGjkBand{0x1p-9, harness::BandSides::two_sided, 0,
                                         "GJK's and EPA's absolute tolerances (about 1e-3): the band they mean at unit scale"};

}  // namespace cc::bullet_oracle
