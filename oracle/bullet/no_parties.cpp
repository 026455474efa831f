// The kinds Bullet gives no second opinion on, one line each with why: each line is the
// kind's unit here (CMake builds no oracle/bullet/kinds/<kind>.cpp for it; see CC_NO_PARTIES).
#include "harness/judging/no_parties.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {

CC_NO_PARTIES(bullet_parties, disc_walls, DiscWalls, "Bullet is 3-D: a stand-in for a disc against segments would test the stand-in, not the maze")
CC_NO_PARTIES(bullet_parties, kdop_kdop, KdopKdop, "Bullet has no k-DOPs")
CC_NO_PARTIES(bullet_parties, tri_tri, TriTri, "Bullet has no exact triangle-triangle test (GImpact's work with a collision margin)")
CC_NO_PARTIES(bullet_parties, tri_tri_intersection, TriTriIntersection, "Bullet has no exact triangle-triangle test (GImpact's contacts work with a collision margin)")
CC_NO_PARTIES(bullet_parties, mesh_mesh_distance, MeshMeshDistance, "Bullet has no distance between triangle meshes (GImpact and its triangle-mesh shapes give contacts; GJK takes convex shapes)")

}  // namespace cc::bullet_oracle
