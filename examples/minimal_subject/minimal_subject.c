/* A whole subject (include/crosscheck/subject.h) in plain C, as a user's first one looks: a box
 * test and a sphere test. Built by docs/subjects.md's five-minute tour:
 *   cc -shared -fPIC -O2 -I include examples/minimal_subject/minimal_subject.c -o libmine.so
 * The box test is exact; the sphere test compares rounded squares, so crosscheck finds the
 * touching and barely overlapping spheres it misses. */
#include <crosscheck/subject.h>

int crosscheck_subject_version(void) { return CROSSCHECK_SUBJECT_VERSION; }

/* Closed boxes meet when every axis's intervals do. */
int crosscheck_aabb_aabb(const cc_aabb* a, const cc_aabb* b) {
  return a->lo.x <= b->hi.x && b->lo.x <= a->hi.x &&
         a->lo.y <= b->hi.y && b->lo.y <= a->hi.y &&
         a->lo.z <= b->hi.z && b->lo.z <= a->hi.z;
}

/* The squared distance of the centres against the squared sum of the radii. */
int crosscheck_sphere_sphere(const cc_sphere* a, const cc_sphere* b) {
  const double dx = a->center.x - b->center.x, dy = a->center.y - b->center.y, dz = a->center.z - b->center.z;
  const double r = a->radius + b->radius;
  return dx * dx + dy * dy + dz * dz <= r * r;
}
