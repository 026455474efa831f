// What several kinds' units share of FCL's narrow phase: collide() and distance() on two shapes,
// GJKSolver_indep::shapeDistance on two triangles, and GJKSolver_libccd::shapeTriangleIntersect of
// a box and a triangle.
#include "oracle/fcl/fcl_shapes.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <fcl/narrowphase/detail/collision_func_matrix.h>
#include <fcl/geometry/shape/triangle_p.h>
#include <fcl/narrowphase/detail/gjk_solver_indep.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

namespace cc::fcl_oracle {

bool fcl_collide(const fcl::CollisionGeometryd& a, const fcl::Transform3d& ta, const fcl::CollisionGeometryd& b,
                 const fcl::Transform3d& tb) {
  fcl::CollisionRequestd request;  // libccd solver, first contact only
  fcl::CollisionResultd result;
  fcl::collide(&a, ta, &b, tb, request, result);
  return result.isCollision();
}

Opinion fcl_indep_distance(const Triangle& a, const Triangle& b) {
  for (const Triangle* t : {&a, &b}) {
    for (const Vec3& p : t->v) {
      if (!finite(p)) return not_applicable("a NaN or infinite coordinate, not asked as libccd's solver is not");
    }
  }
  const fcl::TriangleP<double> ta(to_fcl(a.v[0]), to_fcl(a.v[1]), to_fcl(a.v[2]));
  const fcl::TriangleP<double> tb(to_fcl(b.v[0]), to_fcl(b.v[1]), to_fcl(b.v[2]));
  const fcl::detail::GJKSolver_indep<double> solver;
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  double distance = 0;
  fcl::Vector3d p, q;
  const bool returned =
      run_with_time_limit(kLibccdTimeLimit, [&] { solver.shapeDistance(ta, identity, tb, identity, &distance, &p, &q); });
  if (!returned) return timed_out("did not return within " + std::to_string(kLibccdTimeLimit) + " s (its GJK loop)");
  if (distance < 0) return answered(true);
  harness::Answer answer = harness::Answer::of(distance <= 0);
  answer.params = {distance, p.x(), p.y(), p.z(), q.x(), q.y(), q.z()};
  return answered(answer);
}

Opinion fcl_distance(const fcl::CollisionGeometryd& a, const fcl::Transform3d& ta, const fcl::CollisionGeometryd& b,
                     const fcl::Transform3d& tb, FclDistanceRequest how) {
  fcl::DistanceRequestd request;
  request.enable_nearest_points = true;
  request.enable_signed_distance = how.signed_distance;
  request.gjk_solver_type = how.indep_solver ? fcl::GST_INDEP : fcl::GST_LIBCCD;
  fcl::DistanceResultd result;
  const Guarded outcome = run_guarded(kLibccdTimeLimit, [&] { fcl::distance(&a, ta, &b, tb, request, result); });
  if (outcome == Guarded::timed_out) return timed_out("did not return within " + std::to_string(kLibccdTimeLimit) + " s");
  if (outcome == Guarded::aborted) return failed("aborted (a failed assertion in FCL)");
  const double d = result.min_distance;
  if (d < 0 && !how.signed_distance) return answered(true);
  harness::Answer answer = harness::Answer::of(d <= 0);
  if (d < 0 && how.indep_solver) {
    answer.params = {d};
  } else {
    const fcl::Vector3d &p = result.nearest_points[0], &q = result.nearest_points[1];
    answer.params = {d, p.x(), p.y(), p.z(), q.x(), q.y(), q.z()};
  }
  return answered(answer);
}

Opinion fcl_shape_triangle(const Vec3& half, const Mat3& axes, const Vec3& center, const Triangle& t) {
  // On such input libccd's MPR branches on values it never set (valgrind: "conditional jump
  // depends on uninitialised values" in ccdMPRIntersect): two fresh processes answer the same
  // case differently, so no answer of its can be recorded.
  bool all_finite = finite(half) && finite(center) && finite(t.v[0]) && finite(t.v[1]) && finite(t.v[2]);
  for (const Vec3& axis : axes.col) all_finite = all_finite && finite(axis);
  if (!all_finite) return not_applicable("a NaN or infinite coordinate, on which libccd reads memory it never set");
  const fcl::Boxd box(2 * half.x, 2 * half.y, 2 * half.z);
  const fcl::detail::GJKSolver_libccd<double> solver;
  const fcl::Transform3d tf = to_fcl_transform(axes, center);
  bool hit = false;
  const bool returned = run_with_time_limit(kLibccdTimeLimit, [&] {
    hit = solver.shapeTriangleIntersect(box, tf, to_fcl(t.v[0]), to_fcl(t.v[1]), to_fcl(t.v[2]), nullptr, nullptr, nullptr);
  });
  if (!returned) return timed_out("did not return within " + std::to_string(kLibccdTimeLimit) + " s (libccd's MPR loop)");
  return answered(hit);
}

bool fcl_supports_used_pairs() {
  const fcl::detail::CollisionFunctionMatrix<fcl::detail::GJKSolver_libccd<double>> matrix;
  return matrix.collision_matrix[fcl::GEOM_SPHERE][fcl::GEOM_SPHERE] != nullptr &&
         matrix.collision_matrix[fcl::GEOM_BOX][fcl::GEOM_BOX] != nullptr;
}

}  // namespace cc::fcl_oracle
