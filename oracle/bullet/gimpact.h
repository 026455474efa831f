// Bullet's GImpact on two placed meshes, for the mesh kinds (internal to oracle/bullet).
#pragma once

#include "harness/model/party.h"
#include "harness/model/mesh_query.h"

namespace cc::bullet_oracle {

/// btGImpactCollisionAlgorithm (registered with a collision dispatcher, as Bullet's users
/// register it) on two btGImpactMeshShapes of the meshes (btTriangleMesh of doubles, collision
/// margin 0) placed by their poses, through btCollisionWorld::contactPairTest: the face pairs of
/// the contacts it reports, sorted (for first_only, the first of them). GImpact tests a pair of
/// triangles by their planes (overlap_test_conservative) and then clips each by the other's edge
/// planes (find_triangle_collision_clip_method): a pair whose clipping leaves no point on the
/// other's side of a plane gives no contact.
harness::Opinion gimpact_collide(const harness::MeshPair& meshes, bool first_only);

/// Its band: plane distances and clipping in floating point with margin 0, on triangles moved
/// by the poses in floating point, as FCL's BVHModel parties are judged.
inline constexpr harness::Band kGImpactBand{
    0x1p-38, harness::BandSides::two_sided, 0,
    "plane distances and clipping in floating point (margin 0) on triangles moved by the poses: as FCL's BVHModel"};

}  // namespace cc::bullet_oracle
