// distance() on Obb and sphere trees against exact rational arithmetic: meshes on a dyadic grid
// placed by poses that place them exactly (signed permutations, grid translations), from 2^-300
// to 2^300, apart, touching, crossing and parallel (ties); the distance lies within its bound of
// the least exact distance over every pair of triangles, each witness within its bound of the
// face it names, the witnesses as far apart as the distance says. The configurations are
// counted and each must be met.
#include "collide/bvh_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "collide/procedural_mesh.h"
#include "collide/triangle_distance.h"
#include "oracle/exact/exact_distance.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::QVec3;
using exact::Rational;
using exact::rational;
using Shape = ProceduralMesh::Shape;

constexpr double kGrid = 0x1p-20;  // of the unit: sums of grid values below 2^32 units are exact

// A mesh's vertices rounded to the grid and scaled by `unit` (a power of two): exact sums.
Mesh on_grid(Mesh m, double unit) {
  for (Vec3& v : m.vertices) {
    for (int k = 0; k < 3; ++k) v[k] = std::round(v[k] / kGrid) * kGrid * unit;
  }
  return m;
}

// A signed permutation that is a rotation (exact) and a grid translation.
RigidTransform exact_pose(test::Random& r, double unit, double reach) {
  RigidTransform t;
  const int p = r.below(3);
  const int order[3] = {p, (p + 1 + r.below(2)) % 3, 0};
  int third = 3 - order[0] - order[1];
  const int axes[3] = {order[0], order[1], third};
  for (int c = 0; c < 3; ++c) {
    t.rotation.col[c] = Vec3{};
    t.rotation.col[c][axes[c]] = r.below(2) ? 1.0 : -1.0;
  }
  if (dot(cross(t.rotation.col[0], t.rotation.col[1]), t.rotation.col[2]) < 0) t.rotation.col[2] = -1.0 * t.rotation.col[2];
  for (int k = 0; k < 3; ++k) t.translation[k] = std::round(r.between(-reach, reach) / kGrid) * kGrid * unit;
  return t;
}

Triangle placed(const RigidTransform& pose, const Triangle& t) {
  return {{apply(pose, t.v[0]), apply(pose, t.v[1]), apply(pose, t.v[2])}};
}

template <class BV>
class BvhDistanceExactTest : public ::testing::Test {};
using VolumeTypes = ::testing::Types<Obb, Sphere>;
TYPED_TEST_SUITE(BvhDistanceExactTest, VolumeTypes);

TYPED_TEST(BvhDistanceExactTest, WithinItsBounds) {
  test::Random r(71);
  std::map<std::string, int> met;
  for (int i = 0; i < 120; ++i) {
    const double unit = r.below(3) == 0 ? std::ldexp(1.0, r.in(-300, 300)) : 1.0;
    Mesh a, b;
    RigidTransform pose_a = exact_pose(r, unit, 0.5), pose_b;
    std::string kind;
    switch (r.below(4)) {
      case 0:  // parallel plates, apart by a few grid steps or touching: closest pairs not unique
        kind = "parallel";
        a = on_grid(make_mesh({Shape::plate, 0, 3, 1.0, 0}), unit);
        b = a;
        pose_a = {Mat3::identity(), {}};
        pose_b = {Mat3::identity(), unit * Vec3{0.25, -0.5, double(r.in(0, 3)) * kGrid}};
        break;
      case 1:  // a soup with degenerate faces against a sphere, near each other
        kind = "soup";
        a = on_grid(make_mesh({Shape::soup, std::uint64_t(i), 24, 1.0, 0, 20}), unit);
        b = on_grid(make_mesh({Shape::sphere, 0, 4, 0.5}), unit);
        pose_b = exact_pose(r, unit, 2.0);
        break;
      case 2:  // a torus and a terrain
        kind = "torus";
        a = on_grid(make_mesh({Shape::torus, 0, 4, 1.0}), unit);
        b = on_grid(make_mesh({Shape::terrain, std::uint64_t(i), 4, 1.0}), unit);
        pose_b = exact_pose(r, unit, 1.5);
        break;
      default:  // two spheres, one maybe inside the other
        kind = "spheres";
        a = on_grid(make_mesh({Shape::sphere, 0, 5, 1.0}), unit);
        b = on_grid(make_mesh({Shape::sphere, 0, 3, r.below(2) ? 0.25 : 1.0}), unit);
        pose_b = exact_pose(r, unit, 2.5);
        break;
    }
    const Bvh<TypeParam> ta = build_bvh<TypeParam>(a, {}), tb = build_bvh<TypeParam>(b, {});
    const MeshSeparation got = distance(ta, pose_a, tb, pose_b);
    const Separation& s = got.separation;
    // The least exact distance over the pairs that may hold it: those whose certified lower
    // end (distance_triangle_triangle's, checked in rationals in triangle_distance_test.cpp)
    // is at most the least upper end.
    std::vector<std::pair<Separation, std::pair<Triangle, Triangle>>> pairs;
    double upper = INFINITY;
    for (std::size_t x = 0; x < a.size(); ++x) {
      const Triangle pa = placed(pose_a, a.triangle(x));
      for (std::size_t y = 0; y < b.size(); ++y) {
        const Triangle pb = placed(pose_b, b.triangle(y));
        pairs.push_back({distance_triangle_triangle(pa, pb), {pa, pb}});
        upper = std::min(upper, pairs.back().first.distance + pairs.back().first.distance_error);
      }
    }
    Rational least = -1;
    for (const auto& [sep, pair] : pairs) {
      if (sep.distance - sep.distance_error > upper) continue;
      const Rational d2 = exact::squared_distance_between_triangles(pair.first, pair.second);
      if (least < 0 || d2 < least) least = d2;
    }
    ASSERT_TRUE(exact::root_within(least, rational(s.distance), rational(s.distance_error)))
        << "case " << i << " (" << kind << "): distance " << s.distance << " error " << s.distance_error << " exact "
        << std::sqrt(least.get_d());
    const Rational pe2 = rational(s.point_error) * rational(s.point_error);
    ASSERT_LE(exact::squared_distance_to_triangle(rational(s.on_a), placed(pose_a, a.triangle(got.faces.first))), pe2) << i;
    ASSERT_LE(exact::squared_distance_to_triangle(rational(s.on_b), placed(pose_b, b.triangle(got.faces.second))), pe2) << i;
    const QVec3 w = rational(s.on_b) - rational(s.on_a);
    ASSERT_TRUE(exact::root_within(dot(w, w), rational(s.distance), 2 * rational(s.point_error) + rational(s.distance_error)));
    EXPECT_LE(s.distance_error, 0x1p-40 * 8 * unit) << i;
    ++met[kind];
    ++met[least == 0 ? "touching or crossing" : "apart"];
    if (unit < 1) ++met["tiny"];
    if (unit > 1) ++met["huge"];
  }
  for (const char* c : {"parallel", "soup", "torus", "spheres", "touching or crossing", "apart", "tiny", "huge"}) {
    EXPECT_GT(met[c], 5) << c;
  }
}

}  // namespace
}  // namespace cc
