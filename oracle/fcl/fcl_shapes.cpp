// FCL's narrow phase on shapes and triangles: collide() on spheres and on boxes,
// GJKSolver_libccd::shapeTriangleIntersect, and Intersect::intersect_Triangle.
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/detail/collision_func_matrix.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

namespace cc::fcl_oracle {
namespace {

bool collide(const fcl::CollisionGeometryd& a, const fcl::Transform3d& ta, const fcl::CollisionGeometryd& b,
             const fcl::Transform3d& tb) {
  fcl::CollisionRequestd request;  // libccd solver, first contact only
  fcl::CollisionResultd result;
  fcl::collide(&a, ta, &b, tb, request, result);
  return result.isCollision();
}

Opinion shape_triangle(const std::string& party, const Vec3& half, const Mat3& axes, const Vec3& center,
                       const Triangle& t) {
  const fcl::Boxd box(2 * half.x, 2 * half.y, 2 * half.z);
  const fcl::detail::GJKSolver_libccd<double> solver;
  const fcl::Transform3d tf = to_fcl_transform(axes, center);
  bool hit = false;
  const bool returned = run_with_time_limit(kLibccdTimeLimit, [&] {
    hit = solver.shapeTriangleIntersect(box, tf, to_fcl(t.v[0]), to_fcl(t.v[1]), to_fcl(t.v[2]), nullptr, nullptr, nullptr);
  });
  if (!returned) return failed(party, "did not return within " + std::to_string(kLibccdTimeLimit) + " s (libccd's MPR loop)");
  return answered(party, hit);
}

}  // namespace

bool fcl_supports_used_pairs() {
  const fcl::detail::CollisionFunctionMatrix<fcl::detail::GJKSolver_libccd<double>> matrix;
  return matrix.collision_matrix[fcl::GEOM_SPHERE][fcl::GEOM_SPHERE] != nullptr &&
         matrix.collision_matrix[fcl::GEOM_BOX][fcl::GEOM_BOX] != nullptr;
}

Opinion fcl_collide_spheres(const harness::SphereSphereInput& in) {
  const fcl::Sphered a(in.a.radius), b(in.b.radius);
  return answered("fcl.collide(Sphere,Sphere)", collide(a, to_fcl_transform(Mat3::identity(), in.a.center), b,
                                                        to_fcl_transform(Mat3::identity(), in.b.center)));
}

Opinion fcl_collide_boxes(const harness::ObbObbInput& in) {
  const fcl::Boxd a(2 * in.a.half.x, 2 * in.a.half.y, 2 * in.a.half.z);
  const fcl::Boxd b(2 * in.b.half.x, 2 * in.b.half.y, 2 * in.b.half.z);
  return answered("fcl.collide(Box,Box)", collide(a, to_fcl_transform(in.a.axes, in.a.center), b,
                                                  to_fcl_transform(in.b.axes, in.b.center)));
}

Opinion fcl_shape_triangle(const harness::TriAabbInput& in) {
  // FCL has no AABB shape: the box of the same centre and size, rounded to nearest.
  const Vec3 center = 0.5 * (in.box.lo + in.box.hi), half = 0.5 * (in.box.hi - in.box.lo);
  return shape_triangle("fcl.shapeTriangleIntersect", half, Mat3::identity(), center, in.tri);
}

Opinion fcl_shape_triangle(const harness::TriObbInput& in) {
  return shape_triangle("fcl.shapeTriangleIntersect", in.box.half, in.box.axes, in.box.center, in.tri);
}

Opinion fcl_intersect_triangle(const harness::TriTriInput& in) {
  using fcl::detail::Intersect;
  const auto& a = in.a.v;
  const auto& b = in.b.v;
  return answered("fcl.Intersect::intersect_Triangle",
                  Intersect<double>::intersect_Triangle(to_fcl(a[0]), to_fcl(a[1]), to_fcl(a[2]), to_fcl(b[0]),
                                                        to_fcl(b[1]), to_fcl(b[2])));
}

}  // namespace cc::fcl_oracle
