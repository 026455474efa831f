#include "collide/rigid_transform.h"

namespace cc {

RigidTransform relative(const RigidTransform& a, const RigidTransform& b) {
  RigidTransform r;
  for (int c = 0; c < 3; ++c) r.rotation.col[c] = transpose_times(a.rotation, b.rotation.col[c]);
  r.translation = transpose_times(a.rotation, b.translation - a.translation);
  return r;
}

}  // namespace cc
