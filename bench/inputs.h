// Pre-generated inputs of the benchmarks: the same values for the library and for FCL, from a
// fixed seed, made once before any timing.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "collide/aabb.h"
#include "collide/kdop.h"
#include "collide/obb.h"
#include "collide/ray_aabb.h"
#include "collide/sphere.h"
#include "collide/triangle.h"

namespace cc::bench {

/// The seed of every input set (printed by the bench binary; CROSSCHECK_BENCH_SEED overrides it).
std::uint64_t seed();

/// Pairs per input set: small enough to stay in the first-level caches with FCL's copies.
inline constexpr std::size_t kPairs = 1024;

/// How the pairs of a set are placed.
///  - mixed: shapes of varied sizes at random places in a common region, roughly a third of the
///    pairs overlapping (the share is printed);
///  - near: each pair of the mixed set moved along the line between the shapes' centres to its
///    first contact as the library sees it, then left one representable step inside (even
///    pairs) or outside (odd pairs): every test is decided within a few ULPs.
enum class Mix { mixed, near };
std::string_view to_string(Mix m);

/// Two lists of the same length: pair i is (a[i], b[i]).
template <class A, class B>
struct Pairs {
  std::vector<A> a;
  std::vector<B> b;
};

Pairs<Aabb, Aabb> aabb_pairs(Mix mix);
Pairs<Sphere, Sphere> sphere_pairs(Mix mix);
Pairs<Obb, Obb> obb_pairs(Mix mix);
Pairs<Triangle, Obb> triangle_obb_pairs(Mix mix);
Pairs<Triangle, Triangle> triangle_pairs(Mix mix);

/// Point clouds for k-DOP fitting and overlap: pair i is two clouds of kCloudPoints points
/// each (the vertices of a few neighbouring triangles, as a hierarchy's node holds them); the
/// near mix is brought to contact as the library's k-DOPs (k = 16, 18 or 24) see it.
inline constexpr std::size_t kCloudPoints = 24;
using Cloud = std::vector<Vec3>;
Pairs<Cloud, Cloud> cloud_pairs(Mix mix, int k);

/// Rays and boxes for ray_aabb: kRays rays from a region around kBoxes boxes, a few boxes in a
/// hundred on a ray's path (the share is printed); every 16th ray is parallel to a slab (a zero
/// direction component).
inline constexpr std::size_t kRays = 64, kBoxes = 512;
struct RayScene {
  std::vector<Ray> rays;
  std::vector<Aabb> boxes;
};
RayScene ray_scene();

}  // namespace cc::bench
