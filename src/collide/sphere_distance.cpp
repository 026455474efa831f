#include "collide/sphere_distance.h"

#include "collide/record_sink.h"
#include "collide/sphere_distance_bound.h"

namespace cc {

Separation distance_sphere_sphere(const Sphere& a, const Sphere& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return detail::sphere_sphere(a, b, into);
}

Separation distance_sphere_obb(const Sphere& a, const Obb& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return detail::sphere_obb(a, b, into);
}

}  // namespace cc
