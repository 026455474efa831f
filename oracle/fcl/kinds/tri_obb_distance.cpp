// tri_obb_distance's second opinions: FCL's shapeTriangleDistance of a Box and a triangle with
// nearest points, the call its mesh-against-shape distance traversal makes on each triangle,
// asked of both GJK solvers (libccd's and FCL's own indep). Unsigned: where they meet it gives
// -1 and no points, so only the hit is judged. GJK's tolerance (1e-6) is absolute.
// fcl::distance() has no TriangleP-Box pair ("not supported"), and a signed distance on a
// TriangleP is no opinion: libccd's shapeSignedDistance crashes on it (a null support function)
// and the indep solver's gives -1 where they meet, as shapeTriangleDistance does.
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/detail/gjk_solver_indep.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include <string>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_shapes.h"
#include "oracle/fcl/parties.h"
#include "oracle/fcl/time_limit.h"

namespace cc::fcl_oracle {
namespace {

using harness::TriObbDistanceInput;

template <class Solver>
Opinion triangle_distance_of(const TriObbDistanceInput& in) {
  bool all_finite = finite(in.tri) && finite(in.box.center) && finite(in.box.half);
  for (const Vec3& axis : in.box.axes.col) all_finite = all_finite && finite(axis);
  if (!all_finite) return not_applicable("a NaN or infinite number, on which libccd reads memory it never set");
  const fcl::Boxd box(2 * in.box.half.x, 2 * in.box.half.y, 2 * in.box.half.z);
  const fcl::Transform3d place = to_fcl_transform(in.box.axes, in.box.center);
  const Solver solver;
  double distance = 0;
  fcl::Vector3d on_box, on_triangle;
  const Guarded outcome = run_guarded(kLibccdTimeLimit, [&] {
    solver.shapeTriangleDistance(box, place, to_fcl(in.tri.v[0]), to_fcl(in.tri.v[1]), to_fcl(in.tri.v[2]), &distance,
                                 &on_box, &on_triangle);
  });
  if (outcome == Guarded::timed_out) return timed_out("did not return within " + std::to_string(kLibccdTimeLimit) + " s");
  if (outcome == Guarded::aborted) return failed("aborted (a failed assertion in FCL)");
  if (distance < 0) return answered(true);
  harness::Answer answer = harness::Answer::of(distance <= 0);
  answer.params = {distance, on_triangle.x(), on_triangle.y(), on_triangle.z(), on_box.x(), on_box.y(), on_box.z()};
  return answered(answer);
}

}  // namespace

template <>
const std::vector<Party<TriObbDistanceInput>>& fcl_parties() {
  static const std::vector<Party<TriObbDistanceInput>> parties = {
      {"fcl.GJKSolver_libccd::shapeTriangleDistance(Box)", kGjkDistanceBand,
       [](const TriObbDistanceInput& in) { return triangle_distance_of<fcl::detail::GJKSolver_libccd<double>>(in); }},
      {"fcl.GJKSolver_indep::shapeTriangleDistance(Box)", kGjkDistanceBand,
       [](const TriObbDistanceInput& in) { return triangle_distance_of<fcl::detail::GJKSolver_indep<double>>(in); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
