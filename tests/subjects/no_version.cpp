// A shared library with a kind's function but no crosscheck_subject_version: not a subject.
#include <crosscheck/subject.h>

extern "C" int crosscheck_aabb_aabb(const cc_aabb*, const cc_aabb*) { return 1; }
