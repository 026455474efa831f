// The bands by kind and by party: the library's for each kind (declared in the kind's unit), and
// each second-opinion party's (declared with its call by its oracle), printed by `crosscheck
// bands` and quoted in the README.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "harness/model/band.h"
#include "harness/model/oracle.h"

namespace cc::harness {

/// The library's band for a kind of query.
Band library_band(QueryKind kind);

/// Whether a party is one of the library's other ways to answer a query ("library.<name>",
/// e.g. the full re-sort beside incremental sweep-and-prune); it is judged by the library's band
/// and, when wrong, is an impl_bug.
constexpr bool is_library_party(std::string_view party) { return party.starts_with("library."); }

/// Every band, for printing: (query or party name, band), the library's for each kind, then
/// each party of `second` once per distinct band it declares; a party with different bands for
/// different kinds is named with the kinds of each, "party (kind, kind)".
std::vector<std::pair<std::string, Band>> all_bands(const SecondOpinion& second);

}  // namespace cc::harness
