// tri_tri's second opinion: FCL's Intersect::intersect_Triangle.
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {

template <>
const std::vector<Party<harness::TriTriInput>>& fcl_parties() {
  static const std::vector<Party<harness::TriTriInput>> parties = {
      {"fcl.Intersect::intersect_Triangle",
       {0x1p-40, BandSides::two_sided, 0, "17-axis SAT in floating point with no tolerance: rounding only"},
       [](const harness::TriTriInput& in) {
         using fcl::detail::Intersect;
         const auto& a = in.a.v;
         const auto& b = in.b.v;
         return answered(Intersect<double>::intersect_Triangle(to_fcl(a[0]), to_fcl(a[1]), to_fcl(a[2]), to_fcl(b[0]),
                                                               to_fcl(b[1]), to_fcl(b[2])));
       }}};
  return parties;
}

}  // namespace cc::fcl_oracle
