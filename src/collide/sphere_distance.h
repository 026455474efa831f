// The signed distance of a ball to another ball or to an oriented box, with witness points
// (separation.h).
#pragma once

#include "collide/obb.h"
#include "collide/separation.h"
#include "collide/sphere.h"

namespace cc {

/// The signed distance between two balls: |b.center - a.center| - a.radius - b.radius, with
/// witness points on the line of the centres. Concentric balls: any direction is a shortest
/// one; the x axis is taken. Swapping a and b swaps the witnesses bit for bit (concentric
/// balls aside) and gives the same distance.
///  - Domain: finite inputs of magnitude at most 2^500, radii >= 0.
///  - distance_error: 8u (|b.center - a.center| + a.radius + b.radius), plus the subnormal
///    slack; point_error: 16u (the larger centre coordinate + the larger radius), plus the slack.
Separation distance_sphere_sphere(const Sphere& a, const Sphere& b);

/// The signed distance between a ball (a) and a box (b): the distance from the centre to the box
/// minus the radius, outside; minus the centre's distance to the box's boundary minus the radius,
/// inside. A centre inside the box (its boundary included) is pushed out through a nearest face
/// (on a tie, the first axis, the + side). on_b is the centre's nearest point of the box's
/// boundary; on_a the ball's point nearest the box outside (the centre less the radius along
/// the direction from on_b to the centre), and inside the centre less the radius along the
/// face's outward normal.
///  - Domain: finite inputs of magnitude at most 2^500, radius and half extents >= 0, axes
///    orthonormal to within kObbOrthonormalTolerance (eta). The box is the parallelepiped its
///    axes span; the bounds hold for it.
///  - distance_error: 16u (|d|_1 + |half|_1 + radius) + 8 eta (|d|_1 + |half|_1), d the centre
///    offset, plus the subnormal slack; point_error: 16u (both centres' largest coordinate + |d|_1
///    + |half|_1 + radius) + 4 eta (radius + |d|_1 + |half|_1), plus the slack.
Separation distance_sphere_obb(const Sphere& a, const Obb& b);

}  // namespace cc
