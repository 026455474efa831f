// The mesh_mesh kind's own pieces (the rest are both mesh kinds', two_meshes.cpp): the two-level
// pipeline as the library's other way to answer, and the object bounds it uses, measured.
#include "harness/kinds/mesh_mesh.h"

#include <algorithm>

#include "collide/collision_world.h"
#include "collide/cube_bound.h"
#include "collide/object_bounds.h"
#include "collide/record_sink.h"
#include "harness/model/mesh_collide.h"

namespace cc::harness {
namespace {

// mesh_mesh through the two-level pipeline: both meshes as objects of a CollisionWorld, bounded
// by fitted_box (refit), bounding_cube or their placed balls, sweep-and-prune (and the balls'
// test), then collide() on the candidate; the pairs of the contact, as (face of a, face of b).
Answer world_pairs(const MeshPair& m, RotationBounds bounds) {
  const CollideOptions options{CollisionMode::all_pairs, m.library.update, m.library.descent};
  return with_bv_type(m.library.bv, [&]<class BV>() {
    CollisionWorld<BV> world(bounds, options);
    const ObjectId a = world.add(m.a.mesh, cached_bvh<BV>(m.a.mesh, m.library.build), m.pose_a);
    world.add(m.b.mesh, cached_bvh<BV>(m.b.mesh, m.library.build), m.pose_b);
    world.broad_phase();
    Answer out;
    for (const ObjectContact& c : world.narrow_phase()) {
      for (const auto& [i, j] : c.triangles) out.pairs.push_back(c.objects.first == a ? FacePair{i, j} : FacePair{j, i});
    }
    std::sort(out.pairs.begin(), out.pairs.end());
    out.hit = !out.pairs.empty();
    return out;
  });
}

// The object bounds of a placed mesh: its fitted box, its radius and its cube, apart from the
// other mesh's (the cube is checked against this mesh's vertices).
void object_bounds(const Mesh& mesh, const RigidTransform& pose, bounds::Records& r) {
  fitted_box(mesh, pose, r);
  bounding_cube(rotation_radius(mesh, r), pose, r);
}

constexpr BoundTerm kBoundTerms[] = {
    {"object_bounds", "placement", "rotation"}, {"object_bounds", "placement", "translation"},
    {"object_bounds", "placement", "total"},    {"object_bounds", "radius", "rounding"},
    {"object_bounds", "radius", "total"},       {"object_bounds", "cube", "orthonormality"},
    {"object_bounds", "cube", "placement"},     {"object_bounds", "cube", "total"}};

}  // namespace

const std::vector<Party<MeshMeshInput>>& Query<MeshMeshInput>::library_parties() {
  static const std::vector<Party<MeshMeshInput>> parties = {
      {"library.collision_world(refit)", band,
       [](const MeshMeshInput& in) { return answered(world_pairs(in.meshes, RotationBounds::refit)); }},
      {"library.collision_world(cube)", band,
       [](const MeshMeshInput& in) { return answered(world_pairs(in.meshes, RotationBounds::bounding_cube)); }},
      {"library.collision_world(sphere)", band,
       [](const MeshMeshInput& in) { return answered(world_pairs(in.meshes, RotationBounds::bounding_sphere)); }}};
  return parties;
}

std::span<const BoundTerm> Query<MeshMeshInput>::bound_terms() { return kBoundTerms; }

void Query<MeshMeshInput>::probe(const MeshMeshInput& in, std::vector<bounds::Records>& records) {
  object_bounds(*in.meshes.a.mesh, in.meshes.pose_a, bounds::next_call(records));
  object_bounds(*in.meshes.b.mesh, in.meshes.pose_b, bounds::next_call(records));
}

}  // namespace cc::harness
