// Poses for mesh queries: drawn the way FCL's own test draws them, and brought to contact.
#pragma once

#include "collide/rigid_transform.h"
#include "harness/generation/choices.h"
#include "harness/model/mesh_query.h"

namespace cc::harness {

/// A rotation as FCL's test utility draws one: R = Rz(c) Ry(b) Rx(a) for Euler angles in
/// [-pi, pi].
Mat3 fcl_style_rotation(Choices& c);

/// A pose as FCL's test utility draws rob.obj's in env.obj: fcl_style_rotation, then a
/// translation in [-3000, 3000]^2 x [0, 3000].
RigidTransform fcl_style_pose(Choices& c);

/// b moved along a random direction until the meshes almost touch: from a placement where they
/// collide (touch_at_vertices in touch.h) out to where b's reach clears a's, bisecting on whether the
/// library finds a colliding pair, down to the last representable step. The result lies on
/// either side of first contact by a few ULPs of the translation (unchanged if no pair is found
/// at the start).
void bisect_to_contact(MeshPair& m, Choices& c);

}  // namespace cc::harness
