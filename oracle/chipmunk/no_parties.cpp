// The kinds Chipmunk gives no second opinion on, one line each with why: each line is the
// kind's unit here (CMake builds no oracle/chipmunk/kinds/<kind>.cpp for it; see CC_NO_PARTIES).
#include "harness/judging/no_parties.h"
#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {

CC_NO_PARTIES(chipmunk_parties, aabb_aabb, AabbAabb, "Chipmunk is 2-D; the boxes are 3-D")
CC_NO_PARTIES(chipmunk_parties, broadphase, Broadphase, "Chipmunk is 2-D: its spatial indexes hold 2-D boxes, these are 3-D")
CC_NO_PARTIES(chipmunk_parties, kdop_kdop, KdopKdop, "Chipmunk is 2-D and has no k-DOPs")
CC_NO_PARTIES(chipmunk_parties, mesh_mesh, MeshMesh, "Chipmunk is 2-D and has no triangle meshes")
CC_NO_PARTIES(chipmunk_parties, mesh_mesh_first, MeshMeshFirst, "Chipmunk is 2-D and has no triangle meshes")
CC_NO_PARTIES(chipmunk_parties, moving_obb, MovingObb, "Chipmunk is 2-D; the boxes are 3-D")
CC_NO_PARTIES(chipmunk_parties, obb_obb, ObbObb, "Chipmunk is 2-D; the boxes are 3-D")
CC_NO_PARTIES(chipmunk_parties, ray_aabb, RayAabb, "Chipmunk is 2-D; the rays and boxes are 3-D")
CC_NO_PARTIES(chipmunk_parties, ray_mesh, RayMesh, "Chipmunk is 2-D and has no triangle meshes")
CC_NO_PARTIES(chipmunk_parties, sphere_sphere, SphereSphere, "Chipmunk is 2-D; the spheres are 3-D")
CC_NO_PARTIES(chipmunk_parties, sphere_obb_distance, SphereObbDistance, "Chipmunk is 2-D; the ball and the box are 3-D")
CC_NO_PARTIES(chipmunk_parties, sphere_sphere_distance, SphereSphereDistance, "Chipmunk is 2-D; the balls are 3-D")
CC_NO_PARTIES(chipmunk_parties, tri_aabb, TriAabb, "Chipmunk is 2-D; the triangle and the box are 3-D")
CC_NO_PARTIES(chipmunk_parties, tri_obb, TriObb, "Chipmunk is 2-D; the triangle and the box are 3-D")
CC_NO_PARTIES(chipmunk_parties, tri_tri, TriTri, "Chipmunk is 2-D; the triangles are 3-D")
CC_NO_PARTIES(chipmunk_parties, tri_tri_intersection, TriTriIntersection, "Chipmunk is 2-D; the triangles are 3-D")
CC_NO_PARTIES(chipmunk_parties, tri_tri_distance, TriTriDistance, "Chipmunk is 2-D; the triangles are 3-D")
CC_NO_PARTIES(chipmunk_parties, mesh_mesh_distance, MeshMeshDistance, "Chipmunk is 2-D; the meshes are 3-D")
CC_NO_PARTIES(chipmunk_parties, obb_obb_distance, ObbObbDistance, "Chipmunk is 2-D; the boxes are 3-D")
CC_NO_PARTIES(chipmunk_parties, tri_obb_distance, TriObbDistance, "Chipmunk is 2-D; the triangle and the box are 3-D")

}  // namespace cc::chipmunk_oracle
