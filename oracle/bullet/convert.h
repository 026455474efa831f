// Conversions from the library's types to Bullet's (internal to oracle/bullet).
#pragma once

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <LinearMath/btTransform.h>

#include "collide/obb.h"
#include "collide/proper_frame.h"

namespace cc::bullet_oracle {

inline btVector3 to_bullet(const Vec3& v) { return {v.x, v.y, v.z}; }

/// A btBoxShape holding exactly these half extents: collision margin 0 and its implicit
/// dimensions set to them (a box's default margin of 0.04 is subtracted and added back, which
/// rounds).
inline void set_half_extents(btBoxShape& shape, const Vec3& half) {
  shape.setMargin(0);
  shape.setImplicitShapeDimensions(to_bullet(half));
}

/// The placement x -> axes x + center, its basis the axes as columns, made proper (a box is
/// symmetric, so negating an axis of a mirror-image frame leaves it unchanged).
inline btTransform placement(const Mat3& axes, const Vec3& center) {
  const Mat3 r = proper_frame(axes);
  btTransform t;
  t.setBasis(btMatrix3x3(r.col[0].x, r.col[1].x, r.col[2].x, r.col[0].y, r.col[1].y, r.col[2].y, r.col[0].z, r.col[1].z,
                         r.col[2].z));
  t.setOrigin(to_bullet(center));
  return t;
}

}  // namespace cc::bullet_oracle
