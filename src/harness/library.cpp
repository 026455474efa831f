#include "harness/library.h"

#include <algorithm>
#include <exception>
#include <map>
#include <stdexcept>

#include "collide/box_pairs.h"
#include "collide/column_sweep.h"
#include "collide/kdop.h"
#include "collide/sweep_and_prune.h"
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
  if (const auto* in = std::get_if<MovingObbInput>(&input)) {
    const auto a = exact_aabb(in->a), b = exact_aabb(in->b);
    if (!a || !b) return {{"library.sweep_aabb_aabb", Opinion::Status::not_applicable, {}, "not two exact axis-aligned boxes"}};
    return {guarded("library.sweep_aabb_aabb",
                    [&] { return sweep_answer(sweep_aabb_aabb(*a, in->a.velocity, *b, in->b.velocity)); })};
  }
  return {};
}

}  // namespace cc::harness
