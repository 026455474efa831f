// The kinds ODE gives no second opinion on, one line each with why: each line is the
// kind's unit here (CMake builds no oracle/ode/kinds/<kind>.cpp for it; see CC_NO_PARTIES).
#include "harness/judging/no_parties.h"
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {

CC_NO_PARTIES(ode_parties, disc_walls, DiscWalls, "ODE's geoms are 3-D: a stand-in would test the stand-in, not the maze")
CC_NO_PARTIES(ode_parties, kdop_kdop, KdopKdop, "ODE has no k-DOPs")
CC_NO_PARTIES(ode_parties, mesh_mesh, MeshMesh, "ODE's trimesh collider merges the contacts of nearby pairs, so the pairs it names are a subset by design (the first-hit kind asks it)")
CC_NO_PARTIES(ode_parties, moving_obb, MovingObb, "ODE has no continuous collision test (its steps are discrete)")
CC_NO_PARTIES(ode_parties, tri_aabb, TriAabb, "not wired yet: a one-triangle dTriMesh against a dBox would be one")
CC_NO_PARTIES(ode_parties, tri_obb, TriObb, "not wired yet: a one-triangle dTriMesh against a dBox would be one")
CC_NO_PARTIES(ode_parties, sphere_obb_distance, SphereObbDistance, "ODE has no distance query (its colliders give contacts; dGeomBoxPointDepth is a point's, not a ball's)")
CC_NO_PARTIES(ode_parties, sphere_sphere_distance, SphereSphereDistance, "ODE has no distance query (its colliders give contacts; dGeomSpherePointDepth is a point's, not a ball's)")
CC_NO_PARTIES(ode_parties, tri_tri_distance, TriTriDistance, "ODE has no distance query (its colliders give contacts)")
CC_NO_PARTIES(ode_parties, tri_tri_intersection, TriTriIntersection, "ODE's triangle contacts are points for dynamics, not the intersection")
CC_NO_PARTIES(ode_parties, mesh_mesh_distance, MeshMeshDistance, "ODE has no distance query (its trimesh colliders give contacts)")
CC_NO_PARTIES(ode_parties, obb_obb_distance, ObbObbDistance, "ODE has no distance query (dBoxBox gives contacts with a depth for dynamics, not the penetration depth)")
CC_NO_PARTIES(ode_parties, tri_obb_distance, TriObbDistance, "ODE has no distance query (a one-triangle dTriMesh against a dBox gives contacts for dynamics, not the distance or the penetration depth)")

}  // namespace cc::ode_oracle
