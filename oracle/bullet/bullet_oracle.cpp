#include "oracle/bullet/bullet_oracle.h"

#include <LinearMath/btScalar.h>

#include <string>

#include "oracle/bullet/parties.h"

static_assert(sizeof(btScalar) == sizeof(double), "Bullet must be built in double precision (bullet-float64)");

namespace cc::bullet_oracle {

std::string_view bullet_version() {
  const int minor = BT_BULLET_VERSION % 100;  // 324: 3.24, 305: 3.05
  static const std::string version =
      std::to_string(BT_BULLET_VERSION / 100) + "." + (minor < 10 ? "0" : "") + std::to_string(minor);
  return version;
}

std::vector<harness::Opinion> BulletSecondOpinion::opinions(const harness::Input& input) const {
  return std::visit([]<class In>(const In& in) { return harness::ask_parties(bullet_parties<In>(), in); }, input);
}

std::vector<harness::PartyBand> BulletSecondOpinion::parties(harness::QueryKind kind) const {
  return harness::with_kind(kind, []<class In>() {
    std::vector<harness::PartyBand> out;
    for (const Party<In>& p : bullet_parties<In>()) out.push_back({p.name, p.band});
    return out;
  });
}

}  // namespace cc::bullet_oracle
