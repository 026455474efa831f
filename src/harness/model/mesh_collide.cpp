#include "harness/model/mesh_collide.h"

#include <map>
#include <tuple>

namespace cc::harness {
namespace {

struct Entry {
  std::weak_ptr<const Mesh> mesh;
  std::shared_ptr<const void> bvh;
};
using Key = std::tuple<const Mesh*, std::string, BuildStrategy, SplitAxis, SplitPoint, int, bool, bool>;

std::map<Key, Entry>& cache() {
  static std::map<Key, Entry> entries;
  return entries;
}

}  // namespace

template <class BV>
std::shared_ptr<const Bvh<BV>> cached_bvh(const std::shared_ptr<const Mesh>& mesh, const BuildOptions& options) {
  auto& entries = cache();
  const Key key{mesh.get(),   BoundingVolume<BV>::name(), options.strategy,   options.axis,
                options.point, options.leaf_size,         options.hull_points, options.hull_graphs};
  if (auto it = entries.find(key); it != entries.end()) {
    if (it->second.mesh.lock() == mesh) return std::static_pointer_cast<const Bvh<BV>>(it->second.bvh);
    entries.erase(it);  // a mesh that died, and another one now at its address
  }
  if (entries.size() > 256) std::erase_if(entries, [](const auto& e) { return e.second.mesh.expired(); });
  auto bvh = std::make_shared<const Bvh<BV>>(build_bvh<BV>(*mesh, options));
  entries[key] = {mesh, bvh};
  return bvh;
}

BuildOptions build_options(const LibraryBvh& library) {
  BuildOptions o = library.build;
  o.hull_points = library.update == BvUpdate::exact;
  o.hull_graphs = library.update == BvUpdate::hill_climbing;
  return o;
}

CollisionResult library_collide(const MeshPair& m, CollisionMode mode) {
  const CollideOptions options{mode, m.library.update, m.library.descent};
  return with_bv_type(m.library.bv, [&]<class BV>() {
    if (m.library.build.strategy == BuildStrategy::lazy_top_down) {  // made anew: a query makes its nodes
      LazyBvh<BV> a(*m.a.mesh, build_options(m.library)), b(*m.b.mesh, build_options(m.library));
      return collide(a, m.pose_a, b, m.pose_b, options);
    }
    const auto a = cached_bvh<BV>(m.a.mesh, build_options(m.library));
    const auto b = cached_bvh<BV>(m.b.mesh, build_options(m.library));
    return collide(*a, m.pose_a, *b, m.pose_b, options);
  });
}

MeshSeparation library_distance(const MeshPair& m) {
  const auto walk = [&]<class BV>() {
    const auto a = cached_bvh<BV>(m.a.mesh, m.library.build), b = cached_bvh<BV>(m.b.mesh, m.library.build);
    return distance(*a, m.pose_a, *b, m.pose_b);
  };
  return m.library.bv == BvType::sphere ? walk.operator()<Sphere>() : walk.operator()<Obb>();
}

RayMeshHit library_ray_mesh(const std::shared_ptr<const Mesh>& mesh, const LibraryBvh& library, const Ray& ray,
                            bool any_hit) {
  return with_bv_type(library.bv, [&]<class BV>() {
    const auto bvh = cached_bvh<BV>(mesh, library.build);
    return any_hit ? ray_mesh_any(*bvh, ray) : ray_mesh_closest(*bvh, ray);
  });
}

}  // namespace cc::harness
