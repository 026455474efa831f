// The certified quantities of the library's tests, as a probe sees them: each quantity as the
// test computed it, the bound it was certified against (error_bounds.h), and what its exact
// counterpart needs. Every certified test has an overload below that records into a Records;
// the plain tests record into NoRecords, which the compiler removes. The overloads return the
// plain tests' answers bit for bit.
#pragma once

#include <vector>

#include "collide/error_bounds.h"
#include "collide/kdop.h"
#include "collide/moving_box.h"
#include "collide/object_bounds.h"
#include "collide/ray_aabb.h"
#include "collide/ray_mesh.h"
#include "collide/ray_triangle.h"
#include "collide/sphere.h"
#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"

namespace cc::bounds {

/// A parameter t computed from (n1 - n2) / (d1 - d2) * 2^exponent (in whatever order of
/// operations) and certified by `widening`: its exact value is that of the recorded doubles.
struct Quotient {
  double n1, n2, d1, d2;
  int exponent;
  double t;
  Widening widening;
};

/// test_sphere_sphere: the offset and the reach scaled by 2^-exponent, squared.
struct SphereSquares {
  Sphere a, b;
  int exponent = 0;
  SphereBound bound;
};

/// fit_kdop: the projection s of a point onto a 2- or 3-term direction, and its pad.
struct KdopProjection {
  KdopDirection direction;
  Vec3 point;
  double s, pad;
};

/// test_obb_obb or sweep_obb_obb: the boxes (velocities 0 for the static test) and the bound of
/// every axis; the axes follow (ObbAxis).
struct ObbTest {
  MovingObb a, b;
  ObbBound bound;
};

/// One axis of an ObbTest: 0-2 a's face normals, 3-5 b's, 6 + 3i + j the edge axis a_i x b_j,
/// computed in a's frame (frame 0) or in b's (frame 1). The projection of the centres' offset
/// at t = 0 and its rate (0 for the static test), and the radii, as computed.
struct ObbAxis {
  int axis = 0;
  int frame = 0;
  double projection = 0, rate = 0, radius_a = 0, radius_b = 0;
};

/// sat::separates: the gap between the projections of set a (a triangle, or the box
/// [box.lo, box.hi]) and of triangle b onto `axis`, as computed.
struct SatAxis {
  Vec3 axis;
  bool a_is_box = false;
  Triangle a_triangle;
  Aabb a_box;
  Triangle b;
  double gap = 0;
  SatBound bound;
};

/// test_triangle_obb: the triangle taken into the box's frame, as computed.
struct FrameChange {
  Triangle world;
  Obb box;
  Triangle local;
  FrameChangeBound bound;
};

/// test_triangle_triangle: (u x v) . w as computed, from u x v as computed.
struct Independence {
  Vec3 u_cross_v, u, v, w;
  double det = 0;
  IndependenceBound bound;
};

/// intersect_ray_triangle: one slab. The translated vertices (triangle - origin) and their
/// projections onto `axis`, and the speed of the scaled direction across it, as computed.
struct RayTriangleSlab {
  Vec3 origin;
  Triangle triangle, translated;
  Vec3 dir_scaled;
  Vec3 axis;
  double projections[3] = {0, 0, 0};
  double speed = 0;
  RayTriangleSlabBound bound;
};

/// ray_mesh_closest: a face hit at t (intersect_ray_triangle's answer), and the traversal's pad.
struct RayMeshFaceHit {
  Ray ray;
  Triangle triangle;
  double t = 0;
  RayMeshPad pad;
};

/// apply(pose, point) as fitted_box computes it: the rotated point, then the placed one.
struct Placement {
  RigidTransform pose;
  Vec3 point, rotated, placed;
  TransformBound bound;
};

/// rotation_radius: sqrt(vertex . vertex) as computed, and padded_radius of it (the result
/// takes the largest).
struct RadiusRoot {
  Vec3 vertex;
  double root = 0, padded = 0;
};

/// bounding_cube: the pose, the terms of the cube's half side, and the cube.
struct Cube {
  RigidTransform pose;
  CubeBound bound;
  Aabb cube;
};

/// Every certified quantity one or more probed calls computed, in the order computed.
struct Records {
  std::vector<Quotient> quotients;
  std::vector<SphereSquares> spheres;
  std::vector<KdopProjection> kdop_projections;
  std::vector<ObbTest> obb_tests;
  std::vector<std::vector<ObbAxis>> obb_axes;  // one list per ObbTest
  std::vector<SatAxis> sat_axes;
  std::vector<FrameChange> frame_changes;
  std::vector<Independence> independences;
  std::vector<RayTriangleSlab> ray_triangle_slabs;
  std::vector<RayMeshFaceHit> ray_mesh_hits;
  std::vector<Placement> placements;
  std::vector<RadiusRoot> radius_roots;
  std::vector<Cube> cubes;

  void add(const Quotient& r) { quotients.push_back(r); }
  void add(const SphereSquares& r) { spheres.push_back(r); }
  void add(const KdopProjection& r) { kdop_projections.push_back(r); }
  void add(const ObbTest& r) { obb_tests.push_back(r), obb_axes.emplace_back(); }
  void add(const ObbAxis& r) { obb_axes.back().push_back(r); }  // after its ObbTest
  void add(const SatAxis& r) { sat_axes.push_back(r); }
  void add(const FrameChange& r) { frame_changes.push_back(r); }
  void add(const Independence& r) { independences.push_back(r); }
  void add(const RayTriangleSlab& r) { ray_triangle_slabs.push_back(r); }
  void add(const RayMeshFaceHit& r) { ray_mesh_hits.push_back(r); }
  void add(const Placement& r) { placements.push_back(r); }
  void add(const RadiusRoot& r) { radius_roots.push_back(r); }
  void add(const Cube& r) { cubes.push_back(r); }
};

/// What the plain tests record into: nothing.
struct NoRecords {
  template <class Record>
  void add(const Record&) {}
};

}  // namespace cc::bounds

namespace cc {

// The certified tests, recording into `records`; each answers as its plain version does.
RayHit intersect_ray_aabb(const Ray& ray, const Aabb& box, bounds::Records& records);
bool test_sphere_sphere(const Sphere& a, const Sphere& b, bounds::Records& records);
template <int K>
Kdop<K> fit_kdop(std::span<const Vec3> points, bounds::Records& records);
bool test_obb_obb(const Obb& a, const Obb& b, bounds::Records& records);
bool test_triangle_aabb(const Triangle& t, const Aabb& box, bounds::Records& records);
bool test_triangle_obb(const Triangle& t, const Obb& box, bounds::Records& records);
bool test_triangle_triangle(const Triangle& a, const Triangle& b, bounds::Records& records);
RayTriangleHit intersect_ray_triangle(const Ray& ray, const Triangle& triangle, bounds::Records& records);
template <class BV>
RayMeshHit ray_mesh_closest(const Bvh<BV>& bvh, const Ray& ray, bounds::Records& records);
SweepHit sweep_obb_obb(const MovingObb& a, const MovingObb& b, bounds::Records& records);
SweepHit sweep_aabb_aabb(const Aabb& a, Vec3 va, const Aabb& b, Vec3 vb, bounds::Records& records);
double rotation_radius(const Mesh& mesh, bounds::Records& records);
Aabb bounding_cube(double radius, const RigidTransform& pose, bounds::Records& records);
Aabb fitted_box(const Mesh& mesh, const RigidTransform& pose, bounds::Records& records);

}  // namespace cc
