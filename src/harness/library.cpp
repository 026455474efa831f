#include "harness/library.h"

#include "collide/kdop.h"
#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"

namespace cc::harness {
namespace {

template <int K>
bool kdops_overlap(const KdopKdopInput& in) {
  return test_kdop_kdop(fit_kdop<K>(in.a), fit_kdop<K>(in.b));
}

struct Ask {
  Answer operator()(const RayAabbInput& in) const {
    const RayHit h = intersect_ray_aabb(in.ray, in.box);
    if (!h.hit) return {};
    return {true, {h.t_enter, h.t_exit}};
  }
  Answer operator()(const SphereSphereInput& in) const { return {test_sphere_sphere(in.a, in.b), {}}; }
  Answer operator()(const AabbAabbInput& in) const { return {test_aabb_aabb(in.a, in.b), {}}; }
  Answer operator()(const KdopKdopInput& in) const {
    switch (in.k) {
      case 6: return {kdops_overlap<6>(in), {}};
      case 14: return {kdops_overlap<14>(in), {}};
      case 16: return {kdops_overlap<16>(in), {}};
      case 18: return {kdops_overlap<18>(in), {}};
      case 24: return {kdops_overlap<24>(in), {}};
      case 26: return {kdops_overlap<26>(in), {}};
    }
    return {};  // no such direction set: never generated, rejected when read
  }
  Answer operator()(const ObbObbInput& in) const { return {test_obb_obb(in.a, in.b), {}}; }
  Answer operator()(const TriAabbInput& in) const { return {test_triangle_aabb(in.tri, in.box), {}}; }
  Answer operator()(const TriObbInput& in) const { return {test_triangle_obb(in.tri, in.box), {}}; }
  Answer operator()(const TriTriInput& in) const { return {test_triangle_triangle(in.a, in.b), {}}; }
};

}  // namespace

Answer ask_library(const Input& input) { return std::visit(Ask{}, input); }

}  // namespace cc::harness
