// The kinds FCL and libccd gives no second opinion on, one line each with why: each line is the
// kind's unit here (CMake builds no oracle/fcl/kinds/<kind>.cpp for it; see CC_NO_PARTIES).
#include "harness/judging/no_parties.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

CC_NO_PARTIES(fcl_parties, disc_walls, DiscWalls, "FCL and libccd are 3-D: a disc as a cylinder against a wall as a box would test their GJK and MPR tolerances (about 1e-6) and the stand-in, not the maze")
CC_NO_PARTIES(fcl_parties, ray_mesh, RayMesh, "FCL 0.7 casts no rays")

}  // namespace cc::fcl_oracle
