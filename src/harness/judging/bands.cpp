#include "harness/judging/bands.h"

#include <algorithm>

#include "harness/model/input.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {

Band library_band(QueryKind kind) {
  return pieces_of(kind).band;
}

std::vector<std::pair<std::string, Band>> all_bands(const SecondOpinion& second) {
  std::vector<std::pair<std::string, Band>> rows;
  for (QueryKind kind : kAllQueryKinds) rows.emplace_back("library " + std::string(name(kind)), library_band(kind));
  // Each party once per distinct band, with the kinds that declare it; a party whose band is the
  // same for every kind it answers is named alone.
  struct Declared {
    std::string party;
    Band band;
    std::vector<std::string_view> kinds;
  };
  std::vector<Declared> declared;
  const auto same = [](const Band& a, const Band& b) {
    return a.width == b.width && a.sides == b.sides && a.param_width == b.param_width && a.why == b.why;
  };
  for (QueryKind kind : kAllQueryKinds) {
    for (const PartyBand& p : second.parties(kind)) {
      const auto it = std::find_if(declared.begin(), declared.end(),
                                   [&](const Declared& d) { return d.party == p.party && same(d.band, p.band); });
      if (it == declared.end()) {
        declared.push_back({p.party, p.band, {name(kind)}});
      } else if (std::find(it->kinds.begin(), it->kinds.end(), name(kind)) == it->kinds.end()) {
        it->kinds.push_back(name(kind));
      }
    }
  }
  for (const Declared& d : declared) {
    const bool alone = std::count_if(declared.begin(), declared.end(), [&d](const Declared& e) { return e.party == d.party; }) == 1;
    std::string row = d.party;
    if (!alone) {
      row += " (";
      for (std::size_t i = 0; i < d.kinds.size(); ++i) row += (i ? ", " : "") + std::string(d.kinds[i]);
      row += ")";
    }
    rows.emplace_back(row, d.band);
  }
  return rows;
}

}  // namespace cc::harness
