// A subject that goes wrong in the ways a user's code can: aabb_aabb right except that it
// crashes on boxes whose first lower corner has x = 0.25 exactly and hangs on x = 0.75 exactly;
// sphere_sphere returns neither 0 nor 1; it exports a function named for tri_tri_intersection,
// which the interface does not declare (and which would crash if called).
#include <crosscheck/subject.h>
#include <unistd.h>

#include <csignal>

extern "C" {

int crosscheck_subject_version(void) { return CROSSCHECK_SUBJECT_VERSION; }

int crosscheck_aabb_aabb(const cc_aabb* a, const cc_aabb* b) {
  if (a->lo.x == 0.25) std::raise(SIGSEGV);
  while (a->lo.x == 0.75) pause();
  return a->lo.x <= b->hi.x && b->lo.x <= a->hi.x && a->lo.y <= b->hi.y && b->lo.y <= a->hi.y && a->lo.z <= b->hi.z &&
         b->lo.z <= a->hi.z;
}

int crosscheck_sphere_sphere(const cc_sphere*, const cc_sphere*) { return 7; }

int crosscheck_tri_tri_intersection(const cc_triangle*, const cc_triangle*) {
  std::raise(SIGSEGV);
  return 0;
}

}  // extern "C"
