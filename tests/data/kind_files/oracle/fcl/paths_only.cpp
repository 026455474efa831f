// A tree for `crosscheck kind-files` (tests/CMakeLists.txt): paths into FCL's and the library's
// headers are their folders and files, not the kinds that share their names.
#include <fcl/broadphase/broadphase_SaP.h>
#include "collide/ray_aabb.h"
