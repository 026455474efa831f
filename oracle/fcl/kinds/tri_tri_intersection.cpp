// tri_tri_intersection's second opinion: FCL's Intersect::intersect_Triangle with its contact
// output, the call FCL's mesh traversal makes when contacts are asked for. Only its hit is judged:
// the contacts it gives are the deepest vertices of one triangle below the other's plane (at most
// two, with a depth and a normal), not where the triangles meet, so they are not corners of a n b.
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::TriTriIntersectionInput>>& fcl_parties() {
  static const std::vector<Party<harness::TriTriIntersectionInput>> parties = {
      {"fcl.Intersect::intersect_Triangle(contacts)",
       {0x1p-40, BandSides::two_sided, 0, "17-axis SAT in floating point with no tolerance: rounding only"},
       [](const harness::TriTriIntersectionInput& in) {
         using fcl::detail::Intersect;
         const auto& a = in.a.v;
         const auto& b = in.b.v;
         fcl::Vector3d contacts[2];
         unsigned int count = 0;
         double depth = 0;
         fcl::Vector3d normal;
         return answered(Intersect<double>::intersect_Triangle(to_fcl(a[0]), to_fcl(a[1]), to_fcl(a[2]), to_fcl(b[0]),
                                                               to_fcl(b[1]), to_fcl(b[2]), contacts, &count, &depth,
                                                               &normal));
       }}};
  return parties;
}

}  // namespace cc::fcl_oracle
