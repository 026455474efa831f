// Primitive tests, library against FCL on the same pre-generated pairs (bench/inputs.h). A
// benchmark runs one pass over the kPairs pairs per iteration; the table reports ns per test.
// FCL's counterparts are its lowest-level routines for each test, called directly:
//   aabb_aabb      fcl::AABBd::overlap
//   sphere_sphere  fcl::detail::sphereSphereIntersect (what collide() ends in, without its dispatch)
//   kdop_kdop      fcl::KDOPd<k>::overlap on k-DOPs that each party fitted itself
//   kdop_fit       fcl::fit<KDOPd<k>> (FCL's generic fitter: one += per point)
//   obb_obb        fcl::OBBd::overlap
//   tri_obb        fcl::detail::GJKSolver_libccd<double>::shapeTriangleIntersect on a Boxd
//   tri_tri        fcl::detail::Intersect<double>::intersect_Triangle
//   tri_tri_intersection  the same with its contact output (what FCL's mesh traversal calls
//                  when contacts are asked for): the library's corners against FCL's contacts
//   distance_sphere_sphere  fcl::detail::sphereSphereDistance, with nearest points
//   distance_sphere_obb     fcl::detail::sphereBoxDistance, with nearest points (FCL gives -1
//                  for overlapping shapes; the library their signed distance and witnesses)
//   distance_tri_tri        fcl::detail::TriangleDistance::triDistance, with nearest points
//   distance_obb_obb        fcl::detail::GJKSolver_libccd::shapeDistance on two Boxd, with nearest
//                  points (libccd's GJK, FCL's default for distance(); it gives -1 for boxes that
//                  meet, the library their signed distance, the depth, and witnesses)
//   distance_tri_obb        fcl::detail::GJKSolver_libccd::shapeTriangleDistance on a Boxd, with
//                  nearest points (what FCL's mesh-against-shape distance calls on each
//                  triangle; -1 where they meet, the library their signed distance)
// A distance row counts the pairs nearer than 0.1, so that the answers are used.
#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/kDOP.h>
#include <fcl/math/bv/utility.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/sphere_box.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/sphere_sphere.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/triangle_distance.h>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

#include <memory>
#include <string>

#include "bench/inputs.h"
#include "bench/suites.h"
#include "collide/kdop.h"
#include "collide/obb_distance.h"
#include "collide/sphere_distance.h"
#include "collide/triangle_box.h"
#include "collide/triangle_box_distance.h"
#include "collide/triangle_distance.h"
#include "collide/triangle_intersection.h"
#include "collide/triangle_triangle.h"
#include "oracle/fcl/convert.h"

namespace cc::bench {
namespace {

using fcl_oracle::to_fcl;

// Registers name/lib and name/fcl: each runs `test` over every pair of its own copy of the
// inputs, counting hits (so nothing is optimised away, and both parties' hit shares show).
template <class LibA, class LibB, class FclA, class FclB, class LibTest, class FclTest>
void register_pair(const std::string& name, std::shared_ptr<const Pairs<LibA, LibB>> lib, LibTest lib_test,
                   std::shared_ptr<const Pairs<FclA, FclB>> fcl, FclTest fcl_test) {
  const auto run = [](benchmark::State& state, const auto& pairs, auto test) {
    const std::size_t n = pairs->a.size();
    std::size_t hits = 0;
    for (auto _ : state) {
      hits = 0;
      for (std::size_t i = 0; i < n; ++i) hits += test(pairs->a[i], pairs->b[i]) ? 1 : 0;
      benchmark::DoNotOptimize(hits);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
    state.counters["items_per_iter"] = static_cast<double>(n);
    state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(n);
  };
  benchmark::RegisterBenchmark((name + "/lib").c_str(), [=](benchmark::State& s) { run(s, lib, lib_test); });
  benchmark::RegisterBenchmark((name + "/fcl").c_str(), [=](benchmark::State& s) { run(s, fcl, fcl_test); });
}

template <class A, class B, class ToA, class ToB>
auto converted(const Pairs<A, B>& p, ToA to_a, ToB to_b) {
  using FA = decltype(to_a(p.a[0]));
  using FB = decltype(to_b(p.b[0]));
  auto out = std::make_shared<Pairs<FA, FB>>();
  for (std::size_t i = 0; i < p.a.size(); ++i) out->a.push_back(to_a(p.a[i])), out->b.push_back(to_b(p.b[i]));
  return out;
}

fcl::AABBd fcl_aabb(const Aabb& b) { return fcl::AABBd(to_fcl(b.lo), to_fcl(b.hi)); }

struct FclSphere {
  fcl::Sphered shape;
  fcl::Transform3d tf;
};
FclSphere fcl_sphere(const Sphere& s) {
  FclSphere out{fcl::Sphered(s.radius), fcl::Transform3d::Identity()};
  out.tf.translation() = to_fcl(s.center);
  return out;
}

struct FclBox {
  fcl::Boxd box;
  fcl::Transform3d tf;
};
FclBox fcl_box(const Obb& b) {
  return {fcl::Boxd(2 * b.half.x, 2 * b.half.y, 2 * b.half.z), fcl_oracle::to_fcl_transform(b.axes, b.center)};
}

struct FclTriangle {
  fcl::Vector3d v[3];
};
FclTriangle fcl_triangle(const Triangle& t) { return {{to_fcl(t.v[0]), to_fcl(t.v[1]), to_fcl(t.v[2])}}; }

using FclCloud = std::vector<fcl::Vector3d>;
FclCloud fcl_cloud(const Cloud& c) {
  FclCloud out;
  for (const Vec3& p : c) out.push_back(to_fcl(p));
  return out;
}

template <int K>
fcl::KDOPd<K> fcl_fit(const FclCloud& c) {
  fcl::KDOPd<K> dop;
  fcl::fit(c.data(), static_cast<int>(c.size()), dop);
  return dop;
}

template <int K>
void register_kdop(Mix mix) {
  const auto clouds = cloud_pairs(mix, K);
  // (Built by append: GCC 12 warns falsely, -Wrestrict, on "literal" + std::string here.)
  std::string overlap_name = "kdop_kdop/k", fit_name = "kdop_fit/k";
  overlap_name.append(std::to_string(K)).append("/").append(to_string(mix));
  fit_name.append(std::to_string(K));
  auto lib = std::make_shared<Pairs<Kdop<K>, Kdop<K>>>();
  auto fcl = std::make_shared<Pairs<fcl::KDOPd<K>, fcl::KDOPd<K>>>();
  for (std::size_t i = 0; i < clouds.a.size(); ++i) {
    lib->a.push_back(fit_kdop<K>(clouds.a[i])), lib->b.push_back(fit_kdop<K>(clouds.b[i]));
    fcl->a.push_back(fcl_fit<K>(fcl_cloud(clouds.a[i]))), fcl->b.push_back(fcl_fit<K>(fcl_cloud(clouds.b[i])));
  }
  register_pair(overlap_name, std::shared_ptr<const Pairs<Kdop<K>, Kdop<K>>>(lib),
                [](const Kdop<K>& a, const Kdop<K>& b) { return test_kdop_kdop(a, b); },
                std::shared_ptr<const Pairs<fcl::KDOPd<K>, fcl::KDOPd<K>>>(fcl),
                [](const fcl::KDOPd<K>& a, const fcl::KDOPd<K>& b) { return a.overlap(b); });
  if (mix != Mix::mixed) return;
  // Fitting: one cloud per test (the a side of each pair), the fitted k-DOP's first slab summed.
  auto lib_clouds = std::make_shared<const Pairs<Cloud, int>>(Pairs<Cloud, int>{clouds.a, std::vector<int>(clouds.a.size())});
  auto fcl_clouds = converted(Pairs<Cloud, int>{clouds.a, std::vector<int>(clouds.a.size())}, fcl_cloud, [](int) { return 0; });
  register_pair(
      fit_name, lib_clouds, [](const Cloud& c, int) { return fit_kdop<K>(c).lo[K / 2 - 1] < 0; },
      std::shared_ptr<const Pairs<FclCloud, int>>(fcl_clouds),
      [](const FclCloud& c, int) { return fcl_fit<K>(c).dist(K / 2 - 1) < 0; });
}

// The distance rows: the library's signed distance with witnesses against FCL's routines for
// the same pairs (sphere_pairs, obb_pairs, triangle_pairs and triangle_obb_pairs; the ball-box
// pairs take the balls of one and the boxes of the other).
void register_distance_benchmarks(Mix mix) {
  constexpr double kNear = 0.1;
  // (Names built by append: GCC 12 warns falsely, -Wrestrict, on "literal" + std::string here.)
  const auto name = [mix](const char* row) { return std::string(row).append("/").append(to_string(mix)); };
  {
    auto p = std::make_shared<const Pairs<Sphere, Sphere>>(sphere_pairs(mix));
    register_pair(
        name("distance_sphere_sphere"), p,
        [](const Sphere& a, const Sphere& b) { return distance_sphere_sphere(a, b).distance < kNear; },
        std::shared_ptr<const Pairs<FclSphere, FclSphere>>(converted(*p, fcl_sphere, fcl_sphere)),
        [](const FclSphere& a, const FclSphere& b) {
          double d = 0;
          fcl::Vector3d pa, pb;
          fcl::detail::sphereSphereDistance<double>(a.shape, a.tf, b.shape, b.tf, &d, &pa, &pb);
          return d < kNear;
        });
  }
  {
    const Pairs<Sphere, Sphere> spheres = sphere_pairs(mix);
    auto p = std::make_shared<Pairs<Sphere, Obb>>();
    p->a = spheres.a, p->b = obb_pairs(mix).b;
    register_pair(
        name("distance_sphere_obb"), std::shared_ptr<const Pairs<Sphere, Obb>>(p),
        [](const Sphere& a, const Obb& b) { return distance_sphere_obb(a, b).distance < kNear; },
        std::shared_ptr<const Pairs<FclSphere, FclBox>>(converted(*p, fcl_sphere, fcl_box)),
        [](const FclSphere& a, const FclBox& b) {
          double d = 0;
          fcl::Vector3d pa, pb;
          fcl::detail::sphereBoxDistance<double>(a.shape, a.tf, b.box, b.tf, &d, &pa, &pb);
          return d < kNear;
        });
  }
  {
    auto p = std::make_shared<const Pairs<Triangle, Triangle>>(triangle_pairs(mix));
    register_pair(
        name("distance_tri_tri"), p,
        [](const Triangle& a, const Triangle& b) { return distance_triangle_triangle(a, b).distance < kNear; },
        std::shared_ptr<const Pairs<FclTriangle, FclTriangle>>(converted(*p, fcl_triangle, fcl_triangle)),
        [](const FclTriangle& a, const FclTriangle& b) {
          fcl::Vector3d pa, pb;
          return fcl::detail::TriangleDistance<double>::triDistance(a.v[0], a.v[1], a.v[2], b.v[0], b.v[1], b.v[2],
                                                                    pa, pb) < kNear;
        });
  }
  {
    auto p = std::make_shared<const Pairs<Obb, Obb>>(obb_pairs(mix));
    register_pair(
        name("distance_obb_obb"), p, [](const Obb& a, const Obb& b) { return distance_obb_obb(a, b).distance < kNear; },
        std::shared_ptr<const Pairs<FclBox, FclBox>>(converted(*p, fcl_box, fcl_box)), [](const FclBox& a, const FclBox& b) {
          static const fcl::detail::GJKSolver_libccd<double> solver;
          double d = 0;
          fcl::Vector3d pa, pb;
          solver.shapeDistance(a.box, a.tf, b.box, b.tf, &d, &pa, &pb);
          return d < kNear;
        });
  }
  {
    auto p = std::make_shared<const Pairs<Triangle, Obb>>(triangle_obb_pairs(mix));
    register_pair(
        name("distance_tri_obb"), p,
        [](const Triangle& t, const Obb& b) { return distance_triangle_obb(t, b).distance < kNear; },
        std::shared_ptr<const Pairs<FclTriangle, FclBox>>(converted(*p, fcl_triangle, fcl_box)),
        [](const FclTriangle& t, const FclBox& b) {
          static const fcl::detail::GJKSolver_libccd<double> solver;
          double d = 0;
          fcl::Vector3d pb, pt;
          solver.shapeTriangleDistance(b.box, b.tf, t.v[0], t.v[1], t.v[2], &d, &pb, &pt);
          return d < kNear;
        });
  }
}

}  // namespace

void register_primitive_benchmarks() {
  for (Mix mix : {Mix::mixed, Mix::near}) {
    const std::string m = std::string("/").append(to_string(mix));
    {
      auto p = std::make_shared<const Pairs<Aabb, Aabb>>(aabb_pairs(mix));
      register_pair("aabb_aabb" + m, p, test_aabb_aabb, std::shared_ptr<const Pairs<fcl::AABBd, fcl::AABBd>>(converted(*p, fcl_aabb, fcl_aabb)),
                    [](const fcl::AABBd& a, const fcl::AABBd& b) { return a.overlap(b); });
    }
    {
      auto p = std::make_shared<const Pairs<Sphere, Sphere>>(sphere_pairs(mix));
      register_pair("sphere_sphere" + m, p, test_sphere_sphere,
                    std::shared_ptr<const Pairs<FclSphere, FclSphere>>(converted(*p, fcl_sphere, fcl_sphere)),
                    [](const FclSphere& a, const FclSphere& b) {
                      return fcl::detail::sphereSphereIntersect<double>(a.shape, a.tf, b.shape, b.tf, nullptr);
                    });
    }
    {
      auto p = std::make_shared<const Pairs<Obb, Obb>>(obb_pairs(mix));
      register_pair("obb_obb" + m, p, test_obb_obb,
                    std::shared_ptr<const Pairs<fcl::OBBd, fcl::OBBd>>(converted(*p, fcl_oracle::to_fcl_obb, fcl_oracle::to_fcl_obb)),
                    [](const fcl::OBBd& a, const fcl::OBBd& b) { return a.overlap(b); });
    }
    {
      auto p = std::make_shared<const Pairs<Triangle, Obb>>(triangle_obb_pairs(mix));
      register_pair("tri_obb" + m, p, test_triangle_obb,
                    std::shared_ptr<const Pairs<FclTriangle, FclBox>>(converted(*p, fcl_triangle, fcl_box)),
                    [](const FclTriangle& t, const FclBox& b) {
                      static const fcl::detail::GJKSolver_libccd<double> solver;
                      return solver.shapeTriangleIntersect(b.box, b.tf, t.v[0], t.v[1], t.v[2], nullptr, nullptr, nullptr);
                    });
    }
    {
      auto p = std::make_shared<const Pairs<Triangle, Triangle>>(triangle_pairs(mix));
      register_pair("tri_tri" + m, p, test_triangle_triangle,
                    std::shared_ptr<const Pairs<FclTriangle, FclTriangle>>(converted(*p, fcl_triangle, fcl_triangle)),
                    [](const FclTriangle& a, const FclTriangle& b) {
                      return fcl::detail::Intersect<double>::intersect_Triangle(a.v[0], a.v[1], a.v[2], b.v[0], b.v[1], b.v[2]);
                    });
      register_pair(
          "tri_tri_intersection" + m, p, [](const Triangle& a, const Triangle& b) { return !intersect_triangles(a, b).empty(); },
          std::shared_ptr<const Pairs<FclTriangle, FclTriangle>>(converted(*p, fcl_triangle, fcl_triangle)),
          [](const FclTriangle& a, const FclTriangle& b) {
            fcl::Vector3d contacts[2];
            unsigned int count = 0;
            double depth = 0;
            fcl::Vector3d normal;
            return fcl::detail::Intersect<double>::intersect_Triangle(a.v[0], a.v[1], a.v[2], b.v[0], b.v[1], b.v[2],
                                                                      contacts, &count, &depth, &normal);
          });
    }
    register_distance_benchmarks(mix);
    register_kdop<16>(mix);
    register_kdop<18>(mix);
    register_kdop<24>(mix);
  }
}

}  // namespace cc::bench
