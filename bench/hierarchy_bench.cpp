// Hierarchies, library against FCL with the same volume type:
//  - bvh_build/<mesh>/<bv>: build time and bytes per triangle, for env.obj (2180 triangles) and
//    procedural tori of 10,000 and 99,856 triangles (the growth from one to the other). Library:
//    build_bvh with the default options (top down, longest side, midpoint, one triangle per
//    leaf). FCL: BVHModel with its default splitter (bench/fcl_models.h).
//  - bvh_build/<mesh>/<bv>_with_hull_points: the library's Aabb and k-DOP builds with the hull points
//    that only the exact update needs (BuildOptions::hull_points), which FCL has no counterpart
//    of.
//  - bvh_all_pairs/env_rob/<bv>: env.obj against rob.obj, all colliding triangle pairs, over the
//    poses of `crosscheck bvh-report` (100 drawn as FCL's test draws them, 100 brought to near
//    contact, seed 1): library collide() (all pairs, approximate update, descent into the larger
//    volume, the rule FCL's traversal follows) against oracle/fcl's fcl_collide_meshes with the
//    same volume type (OBBd, AABBd, KDOPd<18>).
//  - bvh_distance/env_rob/<bv>: env.obj against rob.obj over the same poses, the distance with
//    a pair of nearest points: library distance() (bvh_distance.h) on Obb and sphere trees
//    against FCL's distance() with nearest points on BVHModel<OBBRSSd> (the obb row, FCL's
//    recommended volume for distance) and <RSSd> (the sphere row: FCL has no sphere trees, and
//    RSS is its volume built for distance). The distances are summed on both sides as a check.
//  - The library's sphere trees are compared with FCL's kIOSd (its nearest: FCL has no tree of
//    plain spheres), on rows named sphere, without a target.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <type_traits>

#include "bench/fcl_models.h"
#include "bench/inputs.h"
#include "bench/suites.h"
#include "collide/bvh_collide.h"
#include "collide/bvh_distance.h"
#include "harness/generation/choices.h"
#include "harness/formats/mesh_files.h"
#include "harness/generation/mesh_poses.h"
#include "harness/model/mesh_query.h"
#include "collide/procedural_mesh.h"
#include "oracle/fcl/parties.h"

namespace cc::bench {
namespace {

const CollideOptions kAllPairsOptions{CollisionMode::all_pairs, BvUpdate::approximate, Descent::larger};

struct BvCase {
  harness::BvType lib;
  FclBv fcl;
  const char* fcl_party;  // oracle/fcl's mesh party of this volume type, if it has one
  std::string row() const { return std::string(harness::to_string(lib)); }
};
const BvCase kCases[] = {
    {harness::BvType::aabb, FclBv::aabb, "fcl.BVHModel<AABBd>"},
    {harness::BvType::obb, FclBv::obb, "fcl.BVHModel<OBBd>"},
    {harness::BvType::kdop16, FclBv::kdop16, nullptr},
    {harness::BvType::kdop18, FclBv::kdop18, "fcl.BVHModel<KDOPd<18>>"},
    {harness::BvType::kdop24, FclBv::kdop24, nullptr},
    {harness::BvType::sphere, FclBv::kios, "fcl.BVHModel<kIOSd>"},
};

// What a library hierarchy occupies: every array it owns, by capacity.
template <class BV>
std::size_t bvh_bytes(const Bvh<BV>& t) {
  const auto points = [](const NodePoints& p) {
    return p.points.capacity() * sizeof(Vec3) + p.range.capacity() * sizeof(p.range[0]);
  };
  return t.nodes.capacity() * sizeof(BvhNode<BV>) + t.order.capacity() * sizeof(std::uint32_t) +
         t.faces.capacity() * sizeof(t.faces[0]) + t.vertices.capacity() * sizeof(Vec3) + points(t.hull_points);
}

std::filesystem::path corpora_root() {
  const char* env = std::getenv("CROSSCHECK_CORPORA");
  return env ? std::filesystem::path(env) : std::filesystem::path(CROSSCHECK_SOURCE_DIR) / "corpora";
}

std::shared_ptr<const Mesh> load(const char* name) {
  const auto folder = harness::mesh_folder(corpora_root());
  const auto path = harness::find_mesh_file(name, folder);
  if (!path) {
    std::fprintf(stderr, "bench: %s not found in %s (set CROSSCHECK_CORPORA)\n", name, folder.string().c_str());
    std::exit(2);
  }
  return harness::load_mesh_file(*path);
}

void register_build(const std::string& mesh_name, std::shared_ptr<const Mesh> mesh, int repetitions) {
  const double triangles = static_cast<double>(mesh->size());
  const auto library = [=](const std::string& name, harness::BvType bv, BuildOptions options) {
    benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
      std::size_t bytes = 0;
      for (auto _ : state) {
        harness::with_bv_type(bv, [&]<class BV>() {
          const Bvh<BV> tree = build_bvh<BV>(*mesh, options);
          bytes = bvh_bytes(tree);
        });
      }
      state.counters["items_per_iter"] = 1;
      state.counters["bytes_per_triangle"] = static_cast<double>(bytes) / triangles;
    })->Iterations(1)->Repetitions(repetitions)->Unit(benchmark::kMillisecond);
  };
  for (const BvCase& c : kCases) {
    const std::string name = "bvh_build/" + mesh_name + "/" + c.row();
    library(name + "/lib", c.lib, BuildOptions{});
    benchmark::RegisterBenchmark((name + "/fcl").c_str(), [=](benchmark::State& state) {
      std::size_t bytes = 0;
      for (auto _ : state) bytes = build_fcl_model(c.fcl, *mesh);
      state.counters["items_per_iter"] = 1;
      state.counters["bytes_per_triangle"] = static_cast<double>(bytes) / triangles;
    })->Iterations(1)->Repetitions(repetitions)->Unit(benchmark::kMillisecond);
  }
  BuildOptions with_hull_points;
  with_hull_points.hull_points = true;
  for (const BvCase& c : kCases) {
    if (harness::moved_whole(c.lib)) continue;  // OBB and sphere trees keep no hull points
    library("bvh_build/" + mesh_name + "/" + c.row() + "_with_hull_points/lib", c.lib, with_hull_points);
  }
}

// The poses of crosscheck bvh-report (src/tool/bvh_report_command.cpp), from the same harness
// functions and seed.
std::shared_ptr<const std::vector<harness::MeshPair>> env_rob_poses(std::shared_ptr<const Mesh> env,
                                                                     std::shared_ptr<const Mesh> rob) {
  harness::MeshPair base;
  base.a.source = base.b.source = harness::MeshRef::Source::file;
  base.a.file = "meshes/env.obj", base.b.file = "meshes/rob.obj";
  base.a.mesh = env, base.b.mesh = rob;
  harness::RandomChoices c(1);
  auto poses = std::make_shared<std::vector<harness::MeshPair>>();
  for (int i = 0; i < 200; ++i) {
    harness::MeshPair m = base;
    if (i >= 100) {
      m.pose_b.rotation = harness::fcl_style_rotation(c);
      harness::bisect_to_contact(m, c);
    } else {
      m.pose_b = harness::fcl_style_pose(c);
    }
    poses->push_back(std::move(m));
  }
  return poses;
}

void register_all_pairs(std::shared_ptr<const Mesh> env, std::shared_ptr<const Mesh> rob) {
  const auto poses = env_rob_poses(env, rob);
  const double queries = static_cast<double>(poses->size());
  for (const BvCase& c : kCases) {
    const std::string name = "bvh_all_pairs/env_rob/" + c.row();
    // Built once, outside the timing, as FCL's models are (fcl_collide_meshes caches them).
    auto trees = std::make_shared<std::function<std::size_t()>>();
    harness::with_bv_type(c.lib, [&]<class BV>() {
      auto a = std::make_shared<const Bvh<BV>>(build_bvh<BV>(*env, BuildOptions{}));
      auto b = std::make_shared<const Bvh<BV>>(build_bvh<BV>(*rob, BuildOptions{}));
      *trees = [a, b, poses] {
        std::size_t pairs = 0;
        for (const harness::MeshPair& m : *poses) {
          pairs += collide(*a, m.pose_a, *b, m.pose_b, kAllPairsOptions).pairs.size();
        }
        return pairs;
      };
    });
    benchmark::RegisterBenchmark((name + "/lib").c_str(), [=](benchmark::State& state) {
      std::size_t pairs = 0;
      for (auto _ : state) benchmark::DoNotOptimize(pairs = (*trees)());
      state.counters["items_per_iter"] = queries;
      state.counters["pairs"] = static_cast<double>(pairs);
    })->Unit(benchmark::kMillisecond);
    if (c.fcl_party == nullptr) continue;
    const std::string party = c.fcl_party;
    fcl_oracle::fcl_collide_meshes(party, poses->front());  // builds and caches FCL's models
    benchmark::RegisterBenchmark((name + "/fcl").c_str(), [=](benchmark::State& state) {
      std::size_t pairs = 0;
      for (auto _ : state) {
        pairs = 0;
        for (const harness::MeshPair& m : *poses) pairs += fcl_oracle::fcl_collide_meshes(party, m).answer.pairs.size();
        benchmark::DoNotOptimize(pairs);
      }
      state.counters["items_per_iter"] = queries;
      state.counters["pairs"] = static_cast<double>(pairs);
    })->Unit(benchmark::kMillisecond);
  }
}

void register_distance(std::shared_ptr<const Mesh> env, std::shared_ptr<const Mesh> rob) {
  const auto poses = env_rob_poses(env, rob);
  const double queries = static_cast<double>(poses->size());
  const auto rows = {std::tuple{harness::BvType::obb, fcl_oracle::Volume::obbrss},
                     std::tuple{harness::BvType::sphere, fcl_oracle::Volume::rss}};
  for (const auto& [lib, fcl] : rows) {
    const std::string name = "bvh_distance/env_rob/" + std::string(harness::to_string(lib));
    // The distances summed, and the counters summed (bv_tests, primitive_tests).
    auto trees = std::make_shared<std::function<double(DistanceCounters&)>>();
    harness::with_bv_type(lib, [&]<class BV>() {
      if constexpr (std::is_same_v<BV, Obb> || std::is_same_v<BV, Sphere>) {
        auto a = std::make_shared<const Bvh<BV>>(build_bvh<BV>(*env, BuildOptions{}));
        auto b = std::make_shared<const Bvh<BV>>(build_bvh<BV>(*rob, BuildOptions{}));
        *trees = [a, b, poses](DistanceCounters& counters) {
          double sum = 0;
          counters = {};
          for (const harness::MeshPair& m : *poses) {
            const MeshSeparation d = distance(*a, m.pose_a, *b, m.pose_b);
            sum += d.separation.distance;
            counters.bv_tests += d.counters.bv_tests;
            counters.primitive_tests += d.counters.primitive_tests;
          }
          return sum;
        };
      }
    });
    benchmark::RegisterBenchmark((name + "/lib").c_str(), [=](benchmark::State& state) {
      double sum = 0;
      DistanceCounters counters;
      for (auto _ : state) benchmark::DoNotOptimize(sum = (*trees)(counters));
      state.counters["items_per_iter"] = queries;
      state.counters["distance_sum"] = sum;
      state.counters["bv_tests"] = static_cast<double>(counters.bv_tests) / queries;
      state.counters["primitive_tests"] = static_cast<double>(counters.primitive_tests) / queries;
    })->Unit(benchmark::kMillisecond);
    (void)fcl_oracle::fcl_mesh_distance(fcl, poses->front());  // builds and caches FCL's models
    benchmark::RegisterBenchmark((name + "/fcl").c_str(), [=, volume = fcl](benchmark::State& state) {
      double sum = 0;
      for (auto _ : state) {
        sum = 0;
        for (const harness::MeshPair& m : *poses) sum += fcl_oracle::fcl_mesh_distance(volume, m).distance;
        benchmark::DoNotOptimize(sum);
      }
      state.counters["items_per_iter"] = queries;
      state.counters["distance_sum"] = sum;
    })->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

void register_hierarchy_benchmarks() {
  const auto env = load("env.obj"), rob = load("rob.obj");
  register_build("env", env, 5);
  ProceduralMesh torus;
  torus.shape = ProceduralMesh::Shape::torus;
  torus.seed = seed();
  torus.resolution = 50;  // 4 n^2 = 10,000 triangles
  register_build("torus10k", std::make_shared<const Mesh>(make_mesh(torus)), 5);
  torus.resolution = 158;  // 99,856 triangles
  register_build("torus100k", std::make_shared<const Mesh>(make_mesh(torus)), 5);
  register_all_pairs(env, rob);
  register_distance(env, rob);
}

}  // namespace cc::bench
