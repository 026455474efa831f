// Inputs whose every value differs from every other, for round-trip tests of the formats: a
// field read back into the wrong place, or two fields swapped, gives another input. The values
// are visited in an order written here, independently of the formats under test.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <type_traits>
#include <vector>

#include "harness/model/input.h"
#include "harness/generation/rotation.h"

namespace cc::test {

/// Doubles that are all different, bit for bit: random signs, exponents across the whole range
/// (subnormals included) and mantissas, and now and then -0, 0, infinities, NaN, the extremes.
class DistinctValues {
 public:
  explicit DistinctValues(std::uint64_t seed, bool finite_only = false) : rng_(seed), finite_only_(finite_only) {}

  double next() {
    for (;;) {
      const double x = draw();
      std::uint64_t bits = 0;
      std::memcpy(&bits, &x, sizeof bits);
      if (used_.insert(bits).second) return x;
    }
  }
  std::uint64_t below(std::uint64_t n) { return rng_() % n; }

 private:
  double draw() {
    static const double special[] = {-0.0,
                                     0.0,
                                     std::numeric_limits<double>::infinity(),
                                     -std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::denorm_min(),
                                     -std::numeric_limits<double>::denorm_min(),
                                     DBL_MAX,
                                     -DBL_MIN,
                                     1.0,
                                     -2.0,
                                     0.5};
    if (rng_() % 8 == 0) {
      const double s = special[rng_() % std::size(special)];
      if (!finite_only_ || std::isfinite(s)) return s;
    }
    const double mantissa = 1 + static_cast<double>(rng_() >> 12) * 0x1p-52;  // [1, 2)
    const int exponent = static_cast<int>(rng_() % 2100) - 1074 - 25;
    const double x = std::ldexp(mantissa, std::min(exponent, 1023));
    return rng_() % 2 ? -x : x;
  }

  std::mt19937_64 rng_;
  bool finite_only_;
  std::set<std::uint64_t> used_;
};

/// Calls f(x) on every double of an input, in a fixed order (meshes given by triangles: every
/// vertex of every face; procedural recipes are not visited, compare them whole).
template <class F>
void for_each_value(harness::Input& input, F&& f) {
  using namespace harness;
  const auto vec = [&](Vec3& v) { f(v.x), f(v.y), f(v.z); };
  const auto box = [&](Aabb& b) { vec(b.lo), vec(b.hi); };
  const auto obb = [&](Obb& b) { vec(b.center), vec(b.half), vec(b.axes.col[0]), vec(b.axes.col[1]), vec(b.axes.col[2]); };
  const auto tri = [&](Triangle& t) { vec(t.v[0]), vec(t.v[1]), vec(t.v[2]); };
  const auto ray = [&](Ray& r) { vec(r.origin), vec(r.dir), f(r.tmin), f(r.tmax); };
  const auto mesh = [&](MeshRef& m) {
    if (m.source != MeshRef::Source::triangles || !m.mesh) return;
    Mesh copy = *m.mesh;
    for (Vec3& v : copy.vertices) vec(v);
    m.mesh = std::make_shared<const Mesh>(std::move(copy));
  };
  const auto pose = [&](RigidTransform& t) {
    for (int i = 0; i < 3; ++i) vec(t.rotation.col[i]);
    vec(t.translation);
  };
  const auto meshes = [&](MeshPair& m) { mesh(m.a), mesh(m.b), pose(m.pose_a), pose(m.pose_b); };
  std::visit(
      [&](auto& in) {
        using T = std::decay_t<decltype(in)>;
        if constexpr (std::is_same_v<T, RayAabbInput>) {
          ray(in.ray), box(in.box);
        } else if constexpr (std::is_same_v<T, SphereSphereInput> || std::is_same_v<T, SphereSphereDistanceInput>) {
          vec(in.a.center), f(in.a.radius), vec(in.b.center), f(in.b.radius);
        } else if constexpr (std::is_same_v<T, SphereObbDistanceInput>) {
          vec(in.ball.center), f(in.ball.radius), obb(in.box);
        } else if constexpr (std::is_same_v<T, AabbAabbInput>) {
          box(in.a), box(in.b);
        } else if constexpr (std::is_same_v<T, KdopKdopInput>) {
          for (Vec3& p : in.a) vec(p);
          for (Vec3& p : in.b) vec(p);
        } else if constexpr (std::is_same_v<T, ObbObbInput> || std::is_same_v<T, ObbObbDistanceInput>) {
          obb(in.a), obb(in.b);
        } else if constexpr (std::is_same_v<T, TriAabbInput>) {
          tri(in.tri), box(in.box);
        } else if constexpr (std::is_same_v<T, TriObbInput> || std::is_same_v<T, TriObbDistanceInput>) {
          tri(in.tri), obb(in.box);
        } else if constexpr (std::is_same_v<T, TriTriInput> || std::is_same_v<T, TriTriIntersectionInput> ||
                             std::is_same_v<T, TriTriDistanceInput>) {
          tri(in.a), tri(in.b);
        } else if constexpr (std::is_same_v<T, MeshMeshInput> || std::is_same_v<T, MeshMeshFirstInput> ||
                             std::is_same_v<T, MeshMeshDistanceInput>) {
          meshes(in.meshes);
        } else if constexpr (std::is_same_v<T, BroadphaseInput>) {
          for (auto& frame : in.frames) {
            for (auto& slot : frame) {
              if (slot) box(*slot);
            }
          }
        } else if constexpr (std::is_same_v<T, RayMeshInput>) {
          mesh(in.mesh), ray(in.ray);
        } else if constexpr (std::is_same_v<T, DiscWallsInput>) {
          f(in.disc.center.x), f(in.disc.center.y), f(in.disc.radius);
          for (Wall& w : in.walls) f(w.a.x), f(w.a.y), f(w.b.x), f(w.b.y);
        } else {
          static_assert(std::is_same_v<T, MovingObbInput>);
          obb(in.a.box), vec(in.a.velocity), obb(in.b.box), vec(in.b.velocity);
        }
      },
      input);
}

/// Every double of an input as its bits, in for_each_value's order, and the input with each of
/// them replaced by 0 (what is left to compare: the shape, the enumerations, the integers).
inline std::vector<std::uint64_t> value_bits(harness::Input& input) {
  std::vector<std::uint64_t> out;
  for_each_value(input, [&](double& x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    out.push_back(bits);
    x = 0;
  });
  return out;
}

/// Where an input may lie: anywhere a case file can say, or within what a fuzz record holds (at
/// most 8 points per k-DOP set, soups of 1 to 4 triangles, a's pose the identity and b's rotation
/// from the table, the default build options, at most 8 boxes and 4 frames, 1 to 8 walls).
enum class Reach { case_file, fuzz_record };

/// An input of the kind with its shape drawn (k, counts, options, which boxes are present) and
/// every double distinct.
inline harness::Input distinct_input(harness::QueryKind kind, DistinctValues& values, Reach reach) {
  using namespace harness;
  const bool record = reach == Reach::fuzz_record;
  const auto count = [&](std::size_t most) { return 1 + values.below(most); };
  const auto soup = [&](std::size_t faces) {
    Mesh m;
    for (std::uint32_t i = 0; i < faces; ++i) {
      m.vertices.insert(m.vertices.end(), 3, Vec3{});
      m.faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    return triangles_mesh(std::move(m));
  };
  const auto library = [&] {
    LibraryBvh l;
    l.bv = kAllBvTypes[values.below(std::size(kAllBvTypes))];
    l.build.strategy = static_cast<BuildStrategy>(values.below(3));
    l.update = values.below(2) ? BvUpdate::exact : BvUpdate::approximate;
    l.descent = values.below(2) ? Descent::larger : Descent::first_model;
    if (!record) {
      l.build.axis = static_cast<SplitAxis>(values.below(4));
      l.build.point = static_cast<SplitPoint>(values.below(3));
      l.build.leaf_size = static_cast<int>(1 + values.below(9));
    }
    return l;
  };
  const auto mesh = [&]() {
    if (record || values.below(3) != 0) return soup(count(4));
    DistinctValues finite(values.below(1u << 30), true);
    ProceduralMesh recipe;
    recipe.shape = static_cast<ProceduralMesh::Shape>(values.below(5));
    recipe.seed = values.below(1000);
    recipe.resolution = static_cast<int>(1 + values.below(3));
    recipe.size = std::fabs(finite.next());
    recipe.thickness = std::fabs(finite.next());
    recipe.degenerate_percent = static_cast<int>(values.below(50));
    return procedural_mesh(recipe);
  };
  const auto mesh_pair = [&] {
    MeshPair m{mesh(), mesh(), {}, {}, library()};
    return m;
  };
  Input in;
  switch (kind) {
    case QueryKind::ray_aabb: in = RayAabbInput{}; break;
    case QueryKind::sphere_sphere: in = SphereSphereInput{}; break;
    case QueryKind::aabb_aabb: in = AabbAabbInput{}; break;
    case QueryKind::kdop_kdop: {
      static constexpr int kKs[] = {6, 14, 16, 18, 24, 26};
      KdopKdopInput k{kKs[values.below(6)], std::vector<Vec3>(count(record ? 8 : 12)),
                      std::vector<Vec3>(count(record ? 8 : 12))};
      in = k;
      break;
    }
    case QueryKind::obb_obb: in = ObbObbInput{}; break;
    case QueryKind::obb_obb_distance: in = ObbObbDistanceInput{}; break;
    case QueryKind::tri_aabb: in = TriAabbInput{}; break;
    case QueryKind::tri_obb: in = TriObbInput{}; break;
    case QueryKind::tri_obb_distance: in = TriObbDistanceInput{}; break;
    case QueryKind::tri_tri: in = TriTriInput{}; break;
    case QueryKind::tri_tri_intersection: in = TriTriIntersectionInput{}; break;
    case QueryKind::tri_tri_distance: in = TriTriDistanceInput{}; break;
    case QueryKind::sphere_sphere_distance: in = SphereSphereDistanceInput{}; break;
    case QueryKind::sphere_obb_distance: in = SphereObbDistanceInput{}; break;
    case QueryKind::mesh_mesh: in = MeshMeshInput{mesh_pair()}; break;
    case QueryKind::mesh_mesh_first: in = MeshMeshFirstInput{mesh_pair()}; break;
    case QueryKind::mesh_mesh_distance: in = MeshMeshDistanceInput{mesh_pair()}; break;
    case QueryKind::broadphase: {
      BroadphaseInput b;
      const std::size_t frames = count(record ? 4 : 6), boxes = count(record ? 8 : 10);
      for (std::size_t f = 0; f < frames; ++f) {
        auto& frame = b.frames.emplace_back();
        for (std::size_t i = 0; i < boxes; ++i) frame.push_back(values.below(4) ? std::optional<Aabb>(Aabb{}) : std::nullopt);
      }
      in = b;
      break;
    }
    case QueryKind::ray_mesh: in = RayMeshInput{mesh(), {}, library()}; break;
    case QueryKind::moving_obb: in = MovingObbInput{}; break;
    case QueryKind::disc_walls: in = DiscWallsInput{{}, std::vector<Wall>(count(record ? 8 : 10))}; break;
  }
  for_each_value(in, [&](double& x) { x = values.next(); });
  if (MeshPair* m = const_cast<MeshPair*>(meshes_of(in)); m != nullptr && record) {
    m->pose_a = {};
    m->pose_b.rotation = table_rotation(values.below(32));
  }
  return in;
}

}  // namespace cc::test
