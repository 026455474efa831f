// distance() on Obb and sphere trees against exact rational arithmetic (oracle/exact's
// exact_mesh_distance, the meshes placed exactly by their poses): procedural meshes, degenerate
// faces among them, from 2^-300 to 2^300, placed by generic rotations (whose floating-point
// placement rounds) and by exact ones (signed permutations and grid translations, where parallel
// plates tie), apart, touching, crossing and nested. The distance lies within its bound of the
// exact one, each witness within its bound of the face it names, the witnesses as far apart as
// the distance says. The configurations are counted and each must be met.
#include "collide/bvh_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "collide/procedural_mesh.h"
#include "harness/model/mesh_query.h"
#include "oracle/exact/exact_distance.h"
#include "oracle/exact/exact_meshes.h"
#include "rotations.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::QTriangle;
using exact::QVec3;
using exact::Rational;
using exact::rational;
using Shape = ProceduralMesh::Shape;

constexpr double kGrid = 0x1p-20;  // of the unit: sums of grid values below 2^32 units are exact

// A mesh's vertices rounded to the grid and scaled by `unit` (a power of two).
Mesh on_grid(Mesh m, double unit) {
  for (Vec3& v : m.vertices) {
    for (int k = 0; k < 3; ++k) v[k] = std::round(v[k] / kGrid) * kGrid * unit;
  }
  return m;
}

// A generic rotation and translation, or a signed permutation that is a rotation and a grid
// translation (placing grid vertices exactly).
RigidTransform draw_pose(test::Random& r, double unit, double reach, bool exact) {
  RigidTransform t;
  if (exact) {
    const int p = r.below(3), q = (p + 1 + r.below(2)) % 3;
    const int axes[3] = {p, q, 3 - p - q};
    for (int c = 0; c < 3; ++c) t.rotation.col[c] = Vec3{}, t.rotation.col[c][axes[c]] = r.below(2) ? 1.0 : -1.0;
    if (dot(cross(t.rotation.col[0], t.rotation.col[1]), t.rotation.col[2]) < 0) t.rotation.col[2] = -1.0 * t.rotation.col[2];
    for (int k = 0; k < 3; ++k) t.translation[k] = std::round(r.between(-reach, reach) / kGrid) * kGrid * unit;
  } else {
    t.rotation = test::rotation(r.between(-3, 3), r.between(-3, 3), r.between(-3, 3));
    t.translation = unit * r.in_cube(reach);
  }
  return t;
}

QTriangle placed_exactly(const Triangle& t, const RigidTransform& pose) {
  QTriangle out;
  for (int k = 0; k < 3; ++k) {
    const QVec3 v = rational(t.v[k]);
    for (int i = 0; i < 3; ++i) out[k][i] = dot(rational(pose.rotation.row(i)), v) + rational(pose.translation[i]);
  }
  return out;
}

template <class BV>
class BvhDistanceExactTest : public ::testing::Test {};
using VolumeTypes = ::testing::Types<Obb, Sphere>;
TYPED_TEST_SUITE(BvhDistanceExactTest, VolumeTypes);

TYPED_TEST(BvhDistanceExactTest, WithinItsBounds) {
  test::Random r(71);
  std::map<std::string, int> met;
  for (int i = 0; i < 48; ++i) {
    const double unit = r.below(3) == 0 ? std::ldexp(1.0, r.in(-300, 300)) : 1.0;
    const bool exact_poses = r.below(2) == 0;
    Mesh a, b;
    RigidTransform pose_a = draw_pose(r, unit, 0.5, exact_poses), pose_b;
    std::string kind;
    switch (r.below(4)) {
      case 0:  // parallel plates, apart by a few grid steps or touching: closest pairs not unique
        kind = "parallel";
        a = on_grid(make_mesh({Shape::plate, 0, 3, 1.0, 0}), unit);
        b = a;
        pose_b = pose_a;
        pose_b.translation = pose_a.translation + unit * (pose_a.rotation * Vec3{0.25, -0.5, double(r.in(0, 3)) * kGrid});
        break;
      case 1:  // a soup with degenerate faces against a sphere, near each other
        kind = "soup";
        a = on_grid(make_mesh({Shape::soup, std::uint64_t(i), 24, 1.0, 0, 20}), unit);
        b = on_grid(make_mesh({Shape::sphere, 0, 4, 0.5}), unit);
        pose_b = draw_pose(r, unit, 2.0, exact_poses);
        break;
      case 2:  // a torus and a terrain
        kind = "torus";
        a = on_grid(make_mesh({Shape::torus, 0, 4, 1.0}), unit);
        b = on_grid(make_mesh({Shape::terrain, std::uint64_t(i), 4, 1.0}), unit);
        pose_b = draw_pose(r, unit, 1.5, exact_poses);
        break;
      default:  // two spheres, one maybe inside the other
        kind = "spheres";
        a = on_grid(make_mesh({Shape::sphere, 0, 5, 1.0}), unit);
        b = on_grid(make_mesh({Shape::sphere, 0, 3, r.below(2) ? 0.25 : 1.0}), unit);
        pose_b = draw_pose(r, unit, 2.5, exact_poses);
        break;
    }
    const Bvh<TypeParam> ta = build_bvh<TypeParam>(a, {}), tb = build_bvh<TypeParam>(b, {});
    const MeshSeparation got = distance(ta, pose_a, tb, pose_b);
    const Separation& s = got.separation;
    harness::MeshPair m;
    m.a = harness::triangles_mesh(a), m.b = harness::triangles_mesh(b);
    m.pose_a = pose_a, m.pose_b = pose_b;
    const exact::ExactMeshDistance want = exact::exact_mesh_distance(m);
    ASSERT_TRUE(want.faces);
    ASSERT_TRUE(exact::root_within(want.squared, rational(s.distance), rational(s.distance_error)))
        << "case " << i << " (" << kind << "): distance " << s.distance << " error " << s.distance_error << " exact "
        << std::sqrt(want.squared.get_d());
    const Rational pe2 = rational(s.point_error) * rational(s.point_error);
    ASSERT_LE(exact::squared_distance_to_triangle(rational(s.on_a), placed_exactly(a.triangle(got.faces.first), pose_a)), pe2) << i;
    ASSERT_LE(exact::squared_distance_to_triangle(rational(s.on_b), placed_exactly(b.triangle(got.faces.second), pose_b)), pe2) << i;
    const QVec3 w = rational(s.on_b) - rational(s.on_a);
    ASSERT_TRUE(exact::root_within(dot(w, w), rational(s.distance), 2 * rational(s.point_error) + rational(s.distance_error)));
    EXPECT_LE(s.distance_error, 0x1p-40 * 8 * unit) << i;
    ++met[kind];
    ++met[want.squared == 0 ? "touching or crossing" : "apart"];
    ++met[exact_poses ? "exact poses" : "generic poses"];
    if (unit < 1) ++met["tiny"];
    if (unit > 1) ++met["huge"];
  }
  for (const char* c : {"parallel", "soup", "torus", "spheres", "touching or crossing", "apart", "tiny", "huge",
                        "exact poses", "generic poses"}) {
    EXPECT_GT(met[c], 2) << c;
  }
}

}  // namespace
}  // namespace cc
