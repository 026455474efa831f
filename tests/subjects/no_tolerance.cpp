// A subject that answers a distance kind without saying how far its distances may be from the
// exact ones (no crosscheck_distance_tolerance): refused when loaded.
#include <crosscheck/subject.h>

#include <cmath>

extern "C" {

int crosscheck_subject_version(void) { return CROSSCHECK_SUBJECT_VERSION; }

int crosscheck_sphere_sphere_distance(const cc_sphere* a, const cc_sphere* b, double* distance, cc_vec3* on_a,
                                      cc_vec3* on_b) {
  const double dx = b->center.x - a->center.x, dy = b->center.y - a->center.y, dz = b->center.z - a->center.z;
  *distance = std::sqrt(dx * dx + dy * dy + dz * dz) - a->radius - b->radius;
  *on_a = a->center, *on_b = b->center;
  return 1;
}

}  // extern "C"
