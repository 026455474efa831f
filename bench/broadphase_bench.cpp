// Broadphase: n boxes (1k, 10k, 100k) moving coherently; one benchmark iteration is one frame:
// move every box, then find the overlapping pairs.
//  - lib_columns: ColumnSweep::move for every box, then update() (insertion sort of the column
//    entries, a sweep of each column, pair changes);
//  - lib_incremental: SweepAndPrune::move for every box, then update() (insertion sort of the
//    endpoint lists, pair changes);
//  - lib_resort: sort_and_sweep from scratch on the frame's boxes (full sort along x);
//  - fcl_sap, fcl_dyntree: fcl::SaPCollisionManager and fcl::DynamicAABBTreeCollisionManager
//    over Boxd objects: setTranslation and computeAABB for every object, update(), then
//    collide() with a callback that counts the candidate pairs (no narrow phase).
// The scene keeps its density as n grows (about 3 neighbours per box, half extents in
// [0.5, 1.5]), so the number of pairs k grows like n; each box moves back and forth along its
// own direction by up to 0.02 per frame, over a cycle of 64 frames shared by all contestants.
#include <benchmark/benchmark.h>
#include <fcl/broadphase/broadphase_SaP.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "bench/inputs.h"
#include "bench/suites.h"
#include "collide/box_pairs.h"
#include "collide/column_sweep.h"
#include "collide/sweep_and_prune.h"

namespace cc::bench {
namespace {

struct Scene {
  std::vector<Vec3> center, half, velocity;
  std::size_t size() const { return center.size(); }
  // The frame's offset along each box's velocity: a triangle wave of period 64 frames.
  static double phase(std::uint64_t frame) {
    const auto f = static_cast<int>(frame % 64);
    return static_cast<double>(f < 32 ? f : 64 - f);
  }
  Aabb box(std::size_t i, double t) const {
    const Vec3 c = center[i] + t * velocity[i];
    return {c - half[i], c + half[i]};
  }
};

std::shared_ptr<const Scene> make_scene(std::size_t n) {
  std::mt19937_64 rng(seed() ^ (0xB0C5ull + n));
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> normal;
  const double side = std::cbrt(64.0 / 3.0 * static_cast<double>(n));
  auto s = std::make_shared<Scene>();
  for (std::size_t i = 0; i < n; ++i) {
    s->center.push_back({side * unit(rng), side * unit(rng), side * unit(rng)});
    s->half.push_back({0.5 + unit(rng), 0.5 + unit(rng), 0.5 + unit(rng)});
    Vec3 v{normal(rng), normal(rng), normal(rng)};
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    s->velocity.push_back((0.02 * unit(rng) / len) * v);
  }
  return s;
}

void set_counters(benchmark::State& state, double pairs) {
  state.counters["items_per_iter"] = 1;
  state.counters["pairs"] = pairs;
}

// A contestant keeps its state from one call of its benchmark function to the next (Google
// Benchmark calls it once per repetition, and more to size the run): it is set up once, on
// the first call, and the frames go on from where the last call stopped.
template <class Broadphase>
struct Incremental {
  Broadphase sap;
  std::vector<ObjectId> ids;
  std::uint64_t frame = 0;
};

template <class Broadphase>
void lib_incremental(benchmark::State& state, const Scene& s, std::unique_ptr<Incremental<Broadphase>>& kept) {
  if (!kept) {
    kept = std::make_unique<Incremental<Broadphase>>();
    for (std::size_t i = 0; i < s.size(); ++i) kept->ids.push_back(kept->sap.add(s.box(i, 0)));
    kept->sap.update();
  }
  Incremental<Broadphase>& c = *kept;
  const std::uint64_t swaps_before = c.sap.swaps();
  for (auto _ : state) {
    const double t = Scene::phase(++c.frame);
    for (std::size_t i = 0; i < s.size(); ++i) c.sap.move(c.ids[i], s.box(i, t));
    benchmark::DoNotOptimize(c.sap.update());
  }
  set_counters(state, static_cast<double>(c.sap.pairs().size()));
  state.counters["swaps"] = static_cast<double>(c.sap.swaps() - swaps_before) / static_cast<double>(state.iterations());
}

void lib_resort(benchmark::State& state, const Scene& s) {
  std::vector<Aabb> boxes(s.size());
  std::uint64_t frame = 0;
  std::size_t pairs = 0;
  for (auto _ : state) {
    const double t = Scene::phase(++frame);
    for (std::size_t i = 0; i < s.size(); ++i) boxes[i] = s.box(i, t);
    pairs = sort_and_sweep(boxes).size();
    benchmark::DoNotOptimize(pairs);
  }
  set_counters(state, static_cast<double>(pairs));
}

bool count_pair(fcl::CollisionObjectd*, fcl::CollisionObjectd*, void* data) {
  ++*static_cast<std::size_t*>(data);
  return false;  // go on
}

template <class Manager>
struct FclState {
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  Manager manager;
  std::uint64_t frame = 0;
};

template <class Manager>
void fcl_manager(benchmark::State& state, const Scene& s, std::unique_ptr<FclState<Manager>>& kept) {
  if (!kept) {
    kept = std::make_unique<FclState<Manager>>();
    std::vector<fcl::CollisionObjectd*> pointers;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Vec3 h = s.half[i];
      auto box = std::make_shared<fcl::Boxd>(2 * h.x, 2 * h.y, 2 * h.z);
      fcl::Transform3d tf = fcl::Transform3d::Identity();
      tf.translation() = fcl::Vector3d(s.center[i].x, s.center[i].y, s.center[i].z);
      kept->objects.push_back(std::make_unique<fcl::CollisionObjectd>(box, tf));
      kept->objects.back()->computeAABB();
      pointers.push_back(kept->objects.back().get());
    }
    kept->manager.registerObjects(pointers);
    kept->manager.setup();
  }
  FclState<Manager>& c = *kept;
  std::size_t pairs = 0;
  for (auto _ : state) {
    const double t = Scene::phase(++c.frame);
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Vec3 p = s.center[i] + t * s.velocity[i];
      c.objects[i]->setTranslation(fcl::Vector3d(p.x, p.y, p.z));
      c.objects[i]->computeAABB();
    }
    c.manager.update();
    pairs = 0;
    c.manager.collide(&pairs, count_pair);
    benchmark::DoNotOptimize(pairs);
  }
  set_counters(state, static_cast<double>(pairs));
}

}  // namespace

void register_broadphase_benchmarks() {
  for (std::size_t n : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}}) {
    const auto scene = make_scene(n);
    const std::string name = "broadphase/" + std::to_string(n) + "/";
    const auto unit = n >= 100000 ? benchmark::kMillisecond : benchmark::kMicrosecond;
    auto columns = std::make_shared<std::unique_ptr<Incremental<ColumnSweep>>>();
    benchmark::RegisterBenchmark((name + "lib_columns").c_str(), [=](benchmark::State& s) {
      lib_incremental(s, *scene, *columns);
    })->Unit(unit);
    auto kept = std::make_shared<std::unique_ptr<Incremental<SweepAndPrune>>>();
    benchmark::RegisterBenchmark((name + "lib_incremental").c_str(), [=](benchmark::State& s) {
      lib_incremental(s, *scene, *kept);
    })->Unit(unit);
    benchmark::RegisterBenchmark((name + "lib_resort").c_str(), [=](benchmark::State& s) {
      lib_resort(s, *scene);
    })->Unit(unit);
    auto sap = std::make_shared<std::unique_ptr<FclState<fcl::SaPCollisionManagerd>>>();
    benchmark::RegisterBenchmark((name + "fcl_sap").c_str(), [=](benchmark::State& s) {
      fcl_manager(s, *scene, *sap);
    })->Unit(unit);
    auto tree = std::make_shared<std::unique_ptr<FclState<fcl::DynamicAABBTreeCollisionManagerd>>>();
    benchmark::RegisterBenchmark((name + "fcl_dyntree").c_str(), [=](benchmark::State& s) {
      fcl_manager(s, *scene, *tree);
    })->Unit(unit);
  }
}

}  // namespace cc::bench
