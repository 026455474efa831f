// The bands by kind and by party: the library's for each kind (declared in the kind's unit),
// printed by `crosscheck bands` with every party's and quoted in the README.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "harness/judging/band.h"
#include "harness/model/query_kind.h"

namespace cc::harness {

/// The library's band for a kind of query.
Band library_band(QueryKind kind);

/// Whether a party is one of the library's other ways to answer a query ("library.<name>",
/// e.g. the full re-sort beside incremental sweep-and-prune); it is judged by the library's band
/// and, when wrong, is an impl_bug.
constexpr bool is_library_party(std::string_view party) { return party.starts_with("library."); }

/// A second-opinion party's band (see FclSecondOpinion for the party names). Throws
/// std::out_of_range for an unknown party.
Band party_band(std::string_view party);

/// Every band, for printing: (query or party name, band).
std::vector<std::pair<std::string, Band>> all_bands();

}  // namespace cc::harness
