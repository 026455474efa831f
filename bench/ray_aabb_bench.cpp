// ray_aabb has no FCL counterpart: nanoseconds per ray-box test, scalar (intersect_ray_aabb on
// a PreparedRay, one box at a time, which also computes the entry and exit parameters) and
// batched (test_ray_aabbs, one ray against kBoxes boxes stored by coordinate), on the same rays
// and boxes. Every ray meets every box in both.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "bench/inputs.h"
#include "bench/suites.h"
#include "collide/ray_aabb_batch.h"

namespace cc::bench {

void register_ray_benchmarks() {
  auto scene = std::make_shared<const RayScene>(ray_scene());
  auto soa = std::make_shared<AabbSoa>();
  for (const Aabb& b : scene->boxes) soa->push_back(b);
  const double tests = static_cast<double>(scene->rays.size() * scene->boxes.size());

  // The two must agree; a benchmark of a wrong answer is worthless.
  std::size_t scalar_hits = 0, batch_hits = 0;
  std::vector<std::uint64_t> hits(hit_words(soa->size()));
  for (const Ray& r : scene->rays) {
    for (const Aabb& b : scene->boxes) scalar_hits += intersect_ray_aabb(r, b).hit;
    batch_hits += test_ray_aabbs(r, *soa, hits);
  }
  if (scalar_hits != batch_hits) {
    std::fprintf(stderr, "bench: test_ray_aabbs found %zu hits, intersect_ray_aabb %zu\n", batch_hits, scalar_hits);
    std::abort();
  }
  const double hit_fraction = static_cast<double>(scalar_hits) / tests;

  benchmark::RegisterBenchmark("ray_aabb/scalar/lib", [=](benchmark::State& state) {
    for (auto _ : state) {
      std::size_t n = 0;
      for (const Ray& r : scene->rays) {
        const PreparedRay prepared(r);
        for (const Aabb& b : scene->boxes) n += intersect_ray_aabb(prepared, b).hit;
      }
      benchmark::DoNotOptimize(n);
    }
    state.counters["items_per_iter"] = tests;
    state.counters["hit_fraction"] = hit_fraction;
  });
  benchmark::RegisterBenchmark("ray_aabb/batched/lib", [=](benchmark::State& state) {
    std::vector<std::uint64_t> out(hit_words(soa->size()));
    for (auto _ : state) {
      std::size_t n = 0;
      for (const Ray& r : scene->rays) n += test_ray_aabbs(r, *soa, out);
      benchmark::DoNotOptimize(n);
      benchmark::DoNotOptimize(out.data());
    }
    state.counters["items_per_iter"] = tests;
    state.counters["hit_fraction"] = hit_fraction;
  });
}

}  // namespace cc::bench
