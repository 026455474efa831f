// kdop_kdop's second opinion: FCL's KDOPd<k>::overlap on the k-DOPs FCL fits to the points
// (k = 16, 18, 24 only).
#include <fcl/math/bv/kDOP.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

template <int N>
Opinion kdop_overlap(const harness::KdopKdopInput& in) {
  const auto fit = [](const std::vector<Vec3>& points) {
    fcl::KDOP<double, N> dop(to_fcl(points[0]));
    for (const Vec3& p : points) dop += to_fcl(p);
    return dop;
  };
  return answered(fit(in.a).overlap(fit(in.b)));
}

Opinion fcl_kdop_overlap(const harness::KdopKdopInput& in) {
  if (in.a.empty() || in.b.empty()) return not_applicable("an empty point set");
  switch (in.k) {
    case 16: return kdop_overlap<16>(in);
    case 18: return kdop_overlap<18>(in);
    case 24: return kdop_overlap<24>(in);
  }
  return not_applicable("FCL has no KDOP<" + std::to_string(in.k) + ">");
}

}  // namespace

template <>
const std::vector<Party<harness::KdopKdopInput>>& fcl_parties() {
  static const std::vector<Party<harness::KdopKdopInput>> parties = {
      {"fcl.KDOPd<k>::overlap",
       {0x1p-49, BandSides::two_sided, 0, "FCL fits with 2- and 3-term sums rounded to nearest, no outward rounding"},
       fcl_kdop_overlap}};
  return parties;
}

}  // namespace cc::fcl_oracle
