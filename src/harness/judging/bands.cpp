#include "harness/judging/bands.h"

#include <algorithm>

#include "harness/model/input.h"

namespace cc::harness {

Band library_band(QueryKind kind) {
  return with_kind(kind, []<class In>() { return Query<In>::band; });
}

std::vector<std::pair<std::string, Band>> all_bands(const SecondOpinion& second) {
  std::vector<std::pair<std::string, Band>> rows;
  for (QueryKind kind : kAllQueryKinds) rows.emplace_back("library " + std::string(name(kind)), library_band(kind));
  for (QueryKind kind : kAllQueryKinds) {
    for (const PartyBand& p : second.parties(kind)) {
      const bool listed = std::any_of(rows.begin(), rows.end(), [&p](const auto& row) { return row.first == p.party; });
      if (!listed) rows.emplace_back(p.party, p.band);
    }
  }
  return rows;
}

}  // namespace cc::harness
