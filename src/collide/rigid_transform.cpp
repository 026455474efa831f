#include "collide/rigid_transform.h"

#include "collide/transform_bound.h"

namespace cc {

double transform_error_bound(const RigidTransform& t, double p_norm1) {
  return bounds::TransformBound{p_norm1, max_abs(t.translation)}.total();
}

RigidTransform relative(const RigidTransform& a, const RigidTransform& b) {
  RigidTransform r;
  for (int c = 0; c < 3; ++c) r.rotation.col[c] = transpose_times(a.rotation, b.rotation.col[c]);
  r.translation = transpose_times(a.rotation, b.translation - a.translation);
  return r;
}

}  // namespace cc
