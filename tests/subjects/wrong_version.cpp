// A subject built against another version of include/crosscheck/subject.h.
#include <crosscheck/subject.h>

extern "C" int crosscheck_subject_version(void) { return CROSSCHECK_SUBJECT_VERSION + 1; }
extern "C" int crosscheck_aabb_aabb(const cc_aabb*, const cc_aabb*) { return 1; }
