// Conversions from the library's types to FCL's (internal to oracle/fcl).
#pragma once

#include <fcl/common/types.h>
#include <fcl/math/bv/OBB.h>

#include "collide/obb.h"
#include "collide/proper_frame.h"

namespace cc::fcl_oracle {

inline fcl::Vector3d to_fcl(const Vec3& v) { return {v.x, v.y, v.z}; }

inline fcl::Matrix3d to_fcl(const Mat3& m) {
  fcl::Matrix3d r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r(i, j) = m(i, j);
  }
  return r;
}

/// The rigid transform x -> axes x + center of a box (FCL's default Transform3d is
/// uninitialised), with the frame made proper.
inline fcl::Transform3d to_fcl_transform(const Mat3& axes, const Vec3& center) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = to_fcl(proper_frame(axes));
  tf.translation() = to_fcl(center);
  return tf;
}

inline fcl::OBBd to_fcl_obb(const Obb& b) {
  fcl::OBBd o;
  o.axis = to_fcl(proper_frame(b.axes));
  o.To = to_fcl(b.center);
  o.extent = to_fcl(b.half);
  return o;
}

}  // namespace cc::fcl_oracle
