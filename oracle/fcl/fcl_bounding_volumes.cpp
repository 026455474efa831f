// FCL's bounding-volume overlap tests: AABBd, OBBd, KDOPd<16|18|24>.
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/kDOP.h>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

template <int N>
Opinion kdop_overlap(const harness::KdopKdopInput& in) {
  const std::string party = "fcl.KDOPd<k>::overlap";
  const auto fit = [](const std::vector<Vec3>& points) {
    fcl::KDOP<double, N> dop(to_fcl(points[0]));
    for (const Vec3& p : points) dop += to_fcl(p);
    return dop;
  };
  return answered(party, fit(in.a).overlap(fit(in.b)));
}

}  // namespace

Opinion fcl_aabb_overlap(const harness::AabbAabbInput& in) {
  const fcl::AABBd a(to_fcl(in.a.lo), to_fcl(in.a.hi)), b(to_fcl(in.b.lo), to_fcl(in.b.hi));
  return answered("fcl.AABBd::overlap", a.overlap(b));
}

Opinion fcl_obb_overlap(const harness::ObbObbInput& in) {
  return answered("fcl.OBBd::overlap", to_fcl_obb(in.a).overlap(to_fcl_obb(in.b)));
}

Opinion fcl_kdop_overlap(const harness::KdopKdopInput& in) {
  const std::string party = "fcl.KDOPd<k>::overlap";
  if (in.a.empty() || in.b.empty()) return not_applicable(party, "an empty point set");
  switch (in.k) {
    case 16: return kdop_overlap<16>(in);
    case 18: return kdop_overlap<18>(in);
    case 24: return kdop_overlap<24>(in);
  }
  return not_applicable(party, "FCL has no KDOP<" + std::to_string(in.k) + ">");
}

}  // namespace cc::fcl_oracle
