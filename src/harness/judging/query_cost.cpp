#include "harness/judging/query_cost.h"

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "collide/bounding_volume.h"
#include "collide/triangle_triangle.h"
#include "harness/judging/median.h"
#include "harness/model/mesh_collide.h"

namespace cc::harness {
namespace {

constexpr std::size_t kSample = 256;
constexpr std::size_t kBatch = 20000;

// The median time per call of `op(i)` for i = 0 .. kBatch-1, over `repeats` batches. `op`
// returns something that depends on its work, so that the work is not optimised away.
template <class Op>
double per_call_ns(int repeats, Op op) {
  std::vector<double> times;
  volatile std::uint64_t sink = 0;
  for (int r = 0; r < repeats; ++r) {
    std::uint64_t acc = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < kBatch; ++i) acc += static_cast<std::uint64_t>(op(i));
    const auto stop = std::chrono::steady_clock::now();
    sink = sink + acc;
    times.push_back(std::chrono::duration<double, std::nano>(stop - start).count() / kBatch);
  }
  return median(times);
}

// Up to kSample indices spread evenly over [0, n).
std::vector<std::size_t> spread(std::size_t n) {
  std::vector<std::size_t> out;
  const std::size_t step = std::max<std::size_t>(1, n / kSample);
  for (std::size_t i = 0; i < n && out.size() < kSample; i += step) out.push_back(i);
  return out;
}

template <class BV>
UnitCosts unit_costs(const Bvh<BV>& a, const Bvh<BV>& b, const RigidTransform& t, BvUpdate update, int repeats) {
  using Traits = BoundingVolume<BV>;
  UnitCosts c;
  if (a.nodes.empty() || b.nodes.empty()) return c;
  const auto na = spread(a.nodes.size()), nb = spread(b.nodes.size());
  std::vector<BV> moved;
  for (std::size_t n : nb) moved.push_back(moved_volume(b, n, t, update));
  c.bv_update = per_call_ns(repeats, [&](std::size_t i) {
    return Traits::center(moved_volume(b, nb[i % nb.size()], t, update)).x > 0;
  });
  c.bv_test = per_call_ns(repeats, [&](std::size_t i) {
    return Traits::overlap(a.nodes[na[i % na.size()]].bv, moved[(i / na.size() + i) % moved.size()]);
  });
  const auto ta = spread(a.faces.size()), tb = spread(b.faces.size());
  std::vector<Triangle> moved_triangles;
  for (std::size_t s : tb) {
    Triangle tri = b.triangle(s);
    for (Vec3& v : tri.v) v = apply(t, v);
    moved_triangles.push_back(tri);
  }
  c.primitive_test = per_call_ns(repeats, [&](std::size_t i) {
    return test_triangle_triangle(a.triangle(ta[i % ta.size()]), moved_triangles[(i / ta.size() + i) % moved_triangles.size()]);
  });
  return c;
}

}  // namespace

UnitCosts measure_unit_costs(const MeshPair& m, int repeats) {
  return with_bv_type(m.library.bv, [&]<class BV>() {
    const auto a = cached_bvh<BV>(m.a.mesh, build_options(m.library));
    const auto b = cached_bvh<BV>(m.b.mesh, build_options(m.library));
    return unit_costs(*a, *b, relative(m.pose_a, m.pose_b), m.library.update, repeats);
  });
}

QueryCost measure_query_cost(const MeshPair& m, CollisionMode mode, int repeats) {
  QueryCost cost;
  cost.counters = library_collide(m, mode).counters;  // builds the hierarchies, once
  cost.unit = measure_unit_costs(m, repeats);
  cost.predicted_ns = static_cast<double>(cost.counters.bv_tests) * cost.unit.bv_test +
                      static_cast<double>(cost.counters.primitive_tests) * cost.unit.primitive_test +
                      static_cast<double>(cost.counters.bv_updates) * cost.unit.bv_update;
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    library_collide(m, mode);  // allocates its result: not optimised away
    times.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count());
  }
  cost.measured_ns = median(times);
  return cost;
}

}  // namespace cc::harness
