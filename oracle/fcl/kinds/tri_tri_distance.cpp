// tri_tri_distance's second opinions: FCL's TriangleDistance::triDistance, the call its mesh
// distance traversal makes on each pair of triangles (floating point, no tolerance; on the hit
// only where it gives 0, as its points are then arbitrary), and GJKSolver_indep's shapeDistance
// on two TriangleP shapes with nearest points (its tolerance, 1e-6, is absolute).
// GJKSolver_libccd is not asked: on two TriangleP, FCL 0.7 hands libccd a null support function
// and every call crashes.
#include <fcl/narrowphase/detail/primitive_shape_algorithm/triangle_distance.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_shapes.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::TriTriDistanceInput>>& fcl_parties() {
  static const std::vector<Party<harness::TriTriDistanceInput>> parties = {
      {"fcl.TriangleDistance::triDistance",
       {0x1p-40, BandSides::two_sided, 0x1p-40, "segment pairs and projections in floating point with no tolerance: rounding only"},
       [](const harness::TriTriDistanceInput& in) {
         const fcl::Vector3d a[3] = {to_fcl(in.a.v[0]), to_fcl(in.a.v[1]), to_fcl(in.a.v[2])};
         const fcl::Vector3d b[3] = {to_fcl(in.b.v[0]), to_fcl(in.b.v[1]), to_fcl(in.b.v[2])};
         fcl::Vector3d p, q;
         const double d = fcl::detail::TriangleDistance<double>::triDistance(a, b, p, q);
         // Overlapping triangles get 0 and "basically a random pair of points" (its header).
         if (d == 0) return answered(true);
         harness::Answer answer = harness::Answer::of(false);
         answer.params = {d, p.x(), p.y(), p.z(), q.x(), q.y(), q.z()};
         return answered(answer);
       }},
      {"fcl.GJKSolver_indep::shapeDistance(TriangleP)", kGjkDistanceBand,
       [](const harness::TriTriDistanceInput& in) { return fcl_indep_distance(in.a, in.b); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
