// A subject that answers no query kind (its one function misnamed).
#include <crosscheck/subject.h>

extern "C" int crosscheck_subject_version(void) { return CROSSCHECK_SUBJECT_VERSION; }
extern "C" int crosscheck_box_box(const cc_aabb*, const cc_aabb*) { return 1; }
