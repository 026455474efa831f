// Tolerance bands: how far from the decision boundary a party may disagree with the exact
// answer and still count as right. Declared once, per query and per party, here; printed by
// `crosscheck bands` and quoted in the README. A band is never widened to make a case pass.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "harness/model/query_kind.h"

namespace cc::harness {

enum class BandSides {
  exact,         // no disagreement is allowed
  conservative,  // only "hit" for shapes apart by at most the width (never "miss" for contact)
  two_sided,     // either way, within the width
};

struct Band {
  double width = 0;        // in units of the exact verdict's margin (relative to the inputs' scale)
  BandSides sides = BandSides::exact;
  double param_width = 0;  // relative error allowed on an answer's parameters (ray t)
  std::string_view why;    // where the width comes from
};

/// The library's band for a kind of query.
Band library_band(QueryKind kind);

/// Whether a party is one of the library's other ways to answer a query ("library.<name>",
/// e.g. the full re-sort beside incremental sweep-and-prune); it is judged by the library's band
/// and, when wrong, is an impl_bug.
constexpr bool is_library_party(std::string_view party) { return party.starts_with("library."); }

/// A second-opinion party's band (see FclSecondOpinion for the party names). Throws
/// std::out_of_range for an unknown party.
Band party_band(std::string_view party);

/// Whether a disagreement lies inside the band: `says_hit` is what the party answered, `margin`
/// the exact margin (> 0 overlapping, < 0 apart).
bool within_band(const Band& band, bool says_hit, double margin);

std::string_view to_string(BandSides sides);

/// Every band, for printing: (query or party name, band).
std::vector<std::pair<std::string, Band>> all_bands();

}  // namespace cc::harness
