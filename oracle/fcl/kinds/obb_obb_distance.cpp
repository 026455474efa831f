// obb_obb_distance's second opinions: FCL's distance() on two Boxes (each placed by its axes, made
// proper, and centre) with nearest points, asked three ways. Unsigned (its default, libccd's
// solver): libccd's GJK, which gives -1 and no points where the boxes meet. Signed with libccd's
// solver: its GJK and, where they meet, its EPA. Signed with the indep solver: FCL's own GJK and
// EPA. GJK's and EPA's tolerance (1e-6) is absolute.
#include <fcl/geometry/shape/box.h>

#include <cmath>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_shapes.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

using harness::ObbObbDistanceInput;

Opinion distance_of(const ObbObbDistanceInput& in, FclDistanceRequest how) {
  bool all_finite = true;
  for (const Obb* b : {&in.a, &in.b}) {
    all_finite = all_finite && finite(b->center) && finite(b->half);
    for (const Vec3& axis : b->axes.col) all_finite = all_finite && finite(axis);
  }
  if (!all_finite) return not_applicable("a NaN or infinite number, on which libccd reads memory it never set");
  const fcl::Boxd a(2 * in.a.half.x, 2 * in.a.half.y, 2 * in.a.half.z);
  const fcl::Boxd b(2 * in.b.half.x, 2 * in.b.half.y, 2 * in.b.half.z);
  return fcl_distance(a, to_fcl_transform(in.a.axes, in.a.center), b, to_fcl_transform(in.b.axes, in.b.center), how);
}

}  // namespace

template <>
const std::vector<Party<ObbObbDistanceInput>>& fcl_parties() {
  static const std::vector<Party<ObbObbDistanceInput>> parties = {
      {"fcl.distance(Box,Box)", kGjkDistanceBand, [](const ObbObbDistanceInput& in) { return distance_of(in, {false, false}); }},
      {"fcl.distance(Box,Box,signed,libccd)", kGjkDistanceBand,
       [](const ObbObbDistanceInput& in) { return distance_of(in, {false, true}); }},
      {"fcl.distance(Box,Box,signed,indep)", kGjkDistanceBand,
       [](const ObbObbDistanceInput& in) { return distance_of(in, {true, true}); }}};
  return parties;
}

}  // namespace cc::fcl_oracle
