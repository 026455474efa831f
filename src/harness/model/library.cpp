#include "harness/model/library.h"

#include <algorithm>
#include <exception>
#include <map>
#include <stdexcept>

#include "collide/box_pairs.h"
#include "collide/collision_world.h"
#include "collide/column_sweep.h"
#include "collide/kdop.h"
#include "collide/ray_aabb_batch.h"
#include "collide/sweep_and_prune.h"
#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"
#include "harness/model/mesh_collide.h"

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

Answer ray_answer(const RayMeshHit& h, bool with_t);
Answer sweep_answer(const SweepHit& h);
template <class Broadphase>
Answer incremental(const BroadphaseInput& in);

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

  Answer operator()(const BroadphaseInput& in) const { return incremental<ColumnSweep>(in); }
  Answer operator()(const RayMeshInput& in) const { return ray_answer(library_ray_mesh(in.mesh.mesh, in.library, in.ray, false), true); }
  Answer operator()(const MovingObbInput& in) const { return sweep_answer(sweep_obb_obb(in.a, in.b)); }

  static Answer pairs(const MeshPair& m, CollisionMode mode) {
    Answer a;
    a.pairs = library_collide(m, mode).pairs;
    a.hit = !a.pairs.empty();
    return a;
  }
};

Answer ray_answer(const RayMeshHit& h, bool with_t) {
  Answer a = answer(h.hit);
  if (!h.hit) return a;
  if (with_t) a.params = {h.t};
  a.pairs = {{h.face, 0}};
  return a;
}

Answer sweep_answer(const SweepHit& h) {
  Answer a = answer(h.hit);
  if (h.hit) a.params = {h.t_first, h.t_last};
  return a;
}

std::vector<FacePair> slot_pairs(const std::vector<ObjectPair>& pairs, const std::vector<std::uint32_t>& slot_of) {
  std::vector<FacePair> out;
  for (const auto& [a, b] : pairs) out.push_back(std::minmax(slot_of[a], slot_of[b]));
  std::sort(out.begin(), out.end());
  return out;
}

// A broadphase (ColumnSweep, SweepAndPrune) over the frames: boxes added, moved and removed as
// the slots say. A box outside the domain makes add() or move() throw: the documented answer is
// then no hit.
template <class Broadphase>
Answer incremental(const BroadphaseInput& in) {
  Answer a;
  try {
    Broadphase broadphase;
    std::map<std::size_t, ObjectId> id_of;   // slot -> id of its box
    std::vector<std::uint32_t> slot_of;      // id -> slot
    for (const auto& frame : in.frames) {
      for (std::size_t i = 0; i < frame.size(); ++i) {
        const auto it = id_of.find(i);
        if (frame[i] && it == id_of.end()) {
          id_of[i] = broadphase.add(*frame[i]);
          slot_of.push_back(static_cast<std::uint32_t>(i));
        } else if (frame[i]) {
          broadphase.move(it->second, *frame[i]);
        } else if (it != id_of.end()) {
          broadphase.remove(it->second);
          id_of.erase(it);
        }
      }
      broadphase.update();
      a.frames.push_back(slot_pairs(broadphase.pairs(), slot_of));
      a.hit |= !a.frames.back().empty();
    }
  } catch (const std::invalid_argument&) {
    return {};
  }
  return a;
}

Answer full_sorts(const BroadphaseInput& in) {
  Answer a;
  for (const auto& frame : in.frames) {
    std::vector<Aabb> boxes;
    std::vector<std::uint32_t> slot_of;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (!frame[i]) continue;
      boxes.push_back(*frame[i]);
      slot_of.push_back(static_cast<std::uint32_t>(i));
    }
    a.frames.push_back(slot_pairs(sort_and_sweep(boxes), slot_of));
    a.hit |= !a.frames.back().empty();
  }
  return a;
}

// An axis-aligned moving box as the Aabb it is, if its bounds are exact.
std::optional<Aabb> exact_aabb(const MovingObb& m) {
  if (!(m.box.axes == Mat3::identity())) return std::nullopt;
  const Aabb box{m.box.center - m.box.half, m.box.center + m.box.half};
  for (int k = 0; k < 3; ++k) {
    // Both bounds exact: they give back the centre and the half extent.
    if ((box.hi[k] + box.lo[k]) * 0.5 != m.box.center[k] || (box.hi[k] - box.lo[k]) * 0.5 != m.box.half[k] ||
        box.hi[k] - m.box.center[k] != m.box.half[k] || m.box.center[k] - box.lo[k] != m.box.half[k]) {
      return std::nullopt;
    }
  }
  return box;
}

// ray_aabb through the batched test: the case's box at place 3 of 11 (in a vector block of 8
// or 4) and at place 10 (in the scalar tail: 11 = 8 + 3 = 2 * 4 + 3), the other places holding
// boxes made from it (moved by its size, inverted, a point at a corner, NaN, unbounded), each
// answered by every kernel this processor runs. The answer is the hit they all give; a kernel or
// a place that differs from the scalar test on any box is a failure (an impl_bug).
Answer batched_ray(const RayAabbInput& in) {
  const Aabb& box = in.box;
  const Vec3 size = box.hi - box.lo;
  const Aabb fillers[9] = {{box.lo + Vec3{size.x, 0, 0}, box.hi + Vec3{size.x, 0, 0}},
                           {box.lo - Vec3{0, size.y, 0}, box.hi - Vec3{0, size.y, 0}},
                           {box.hi, box.lo},
                           {box.lo, box.lo},
                           {box.hi, box.hi},
                           {{box.lo.x, NAN, box.lo.z}, box.hi},
                           {box.lo, {box.hi.x, box.hi.y, INFINITY}},
                           {box.lo + Vec3{0, 0, size.z}, box.hi + Vec3{0, 0, size.z}},
                           {{-box.hi.x, box.lo.y, box.lo.z}, {-box.lo.x, box.hi.y, box.hi.z}}};
  constexpr std::size_t kInBlock = 3, kInTail = 10, kBoxes = 11;
  AabbSoa boxes;
  for (std::size_t i = 0, f = 0; i < kBoxes; ++i) boxes.push_back(i == kInBlock || i == kInTail ? box : fillers[f++]);
  std::vector<std::uint8_t> hits(kBoxes);
  for (simd::Kernel kernel : simd::supported_kernels()) {
    test_ray_aabbs(in.ray, boxes, hits, kernel);
    for (std::size_t i = 0; i < kBoxes; ++i) {
      const bool scalar = intersect_ray_aabb(in.ray, boxes[i]).hit;
      if (hits[i] != (scalar ? 1 : 0)) {
        throw std::logic_error("the " + std::string(simd::to_string(kernel)) + " kernel says " +
                               (hits[i] ? "hit" : "miss") + " for box " + std::to_string(i) + " of " +
                               std::to_string(kBoxes) + (i == kInBlock || i == kInTail ? " (the case's)" : "") +
                               ", intersect_ray_aabb " + (scalar ? "hit" : "miss"));
      }
    }
  }
  return answer(hits[kInBlock] != 0);
}

// mesh_mesh through the two-level pipeline: both meshes as objects of a CollisionWorld, boxed
// by fitted_box (refit) or bounding_cube, sweep-and-prune, then collide() on the candidate; the
// pairs of the contact, as (face of a, face of b).
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

template <class F>
Opinion guarded(std::string party, F f) {
  Opinion o{std::move(party), Opinion::Status::answered, {}, ""};
  try {
    o.answer = f();
  } catch (const std::exception& e) {
    o.status = Opinion::Status::failed;
    o.detail = std::string("exception: ") + e.what();
  }
  return o;
}

}  // namespace

Answer ask_library(const Input& input) { return std::visit(Ask{}, input); }

std::vector<Opinion> library_alternatives(const Input& input) {
  if (const auto* in = std::get_if<BroadphaseInput>(&input)) {
    return {guarded("library.sweep_and_prune", [&] { return incremental<SweepAndPrune>(*in); }),
            guarded("library.sort_and_sweep", [&] { return full_sorts(*in); })};
  }
  if (const auto* in = std::get_if<RayMeshInput>(&input)) {
    return {guarded("library.ray_mesh_any",
                    [&] { return ray_answer(library_ray_mesh(in->mesh.mesh, in->library, in->ray, true), false); }),
            guarded("library.ray_mesh_brute_force", [&] { return ray_answer(ray_mesh_brute_force(*in->mesh.mesh, in->ray), true); })};
  }
  if (const auto* in = std::get_if<RayAabbInput>(&input)) {
    return {guarded("library.test_ray_aabbs", [&] { return batched_ray(*in); })};
  }
  if (const auto* in = std::get_if<MeshMeshInput>(&input)) {
    return {guarded("library.collision_world(refit)", [&] { return world_pairs(in->meshes, RotationBounds::refit); }),
            guarded("library.collision_world(cube)",
                    [&] { return world_pairs(in->meshes, RotationBounds::bounding_cube); })};
  }
  if (const auto* in = std::get_if<MovingObbInput>(&input)) {
    const auto a = exact_aabb(in->a), b = exact_aabb(in->b);
    if (!a || !b) return {{"library.sweep_aabb_aabb", Opinion::Status::not_applicable, {}, "not two exact axis-aligned boxes"}};
    return {guarded("library.sweep_aabb_aabb",
                    [&] { return sweep_answer(sweep_aabb_aabb(*a, in->a.velocity, *b, in->b.velocity)); })};
  }
  return {};
}

}  // namespace cc::harness
