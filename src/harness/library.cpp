#include "harness/library.h"

#include "collide/kdop.h"
#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"
#include "harness/mesh_collide.h"

namespace cc::harness {
namespace {

template <int K>
bool kdops_overlap(const KdopKdopInput& in) {
  return test_kdop_kdop(fit_kdop<K>(in.a), fit_kdop<K>(in.b));
}

Answer answer(bool hit) {
  Answer a;
  a.hit = hit;
  return a;
}

struct Ask {
  Answer operator()(const RayAabbInput& in) const {
    const RayHit h = intersect_ray_aabb(in.ray, in.box);
    if (!h.hit) return {};
    Answer a = answer(true);
    a.params = {h.t_enter, h.t_exit};
    return a;
  }
  Answer operator()(const SphereSphereInput& in) const { return answer(test_sphere_sphere(in.a, in.b)); }
  Answer operator()(const AabbAabbInput& in) const { return answer(test_aabb_aabb(in.a, in.b)); }
  Answer operator()(const KdopKdopInput& in) const {
    switch (in.k) {
      case 6: return answer(kdops_overlap<6>(in));
      case 14: return answer(kdops_overlap<14>(in));
      case 16: return answer(kdops_overlap<16>(in));
      case 18: return answer(kdops_overlap<18>(in));
      case 24: return answer(kdops_overlap<24>(in));
      case 26: return answer(kdops_overlap<26>(in));
    }
    return {};  // no such direction set: never generated, rejected when read
  }
  Answer operator()(const ObbObbInput& in) const { return answer(test_obb_obb(in.a, in.b)); }
  Answer operator()(const TriAabbInput& in) const { return answer(test_triangle_aabb(in.tri, in.box)); }
  Answer operator()(const TriObbInput& in) const { return answer(test_triangle_obb(in.tri, in.box)); }
  Answer operator()(const TriTriInput& in) const { return answer(test_triangle_triangle(in.a, in.b)); }
  Answer operator()(const MeshMeshInput& in) const { return pairs(in.meshes, CollisionMode::all_pairs); }
  Answer operator()(const MeshMeshFirstInput& in) const { return pairs(in.meshes, CollisionMode::first_hit); }

  static Answer pairs(const MeshPair& m, CollisionMode mode) {
    Answer a;
    a.pairs = library_collide(m, mode).pairs;
    a.hit = !a.pairs.empty();
    return a;
  }
};

}  // namespace

Answer ask_library(const Input& input) { return std::visit(Ask{}, input); }

}  // namespace cc::harness
