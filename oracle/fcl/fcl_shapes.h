// FCL's collide() on two shapes, for the kinds' units (internal to oracle/fcl).
#pragma once

#include <fcl/geometry/collision_geometry.h>

#include "oracle/fcl/convert.h"

namespace cc::fcl_oracle {

/// Whether FCL's collide() (libccd solver, first contact only) finds the shapes in contact.
bool fcl_collide(const fcl::CollisionGeometryd& a, const fcl::Transform3d& ta, const fcl::CollisionGeometryd& b,
                 const fcl::Transform3d& tb);

}  // namespace cc::fcl_oracle
