// What a query kind's unit provides to the harness: Query<its input type>, declared in
// src/harness/kinds/<kind>.h with the input and its fields, defined in <kind>.cpp. Everything that
// lists or dispatches kinds reaches a kind through it (and through the registry), so a kind lives
// in one place; a unit that lacks a piece does not compile (QueryUnit, checked for every kind in
// model/input.h). The exact reference's and the second opinions' pieces of a kind are in
// oracle/exact/kinds/<kind>.cpp and oracle/fcl/kinds/<kind>.cpp.
#pragma once

#include <concepts>
#include <span>
#include <string_view>
#include <vector>

#include "harness/model/parts.h"
#include "harness/model/band.h"
#include "harness/judging/party.h"
#include "harness/judging/relation.h"
#include "harness/model/answer.h"

namespace cc::bounds {
struct Records;  // collide/bound_records.h
}  // namespace cc::bounds

namespace cc::harness {

class ValueSource;        // generation/values.h
struct GenerateOptions;   // generation/generate.h
class Configurations;     // judging/configurations.h

/// What kind of configuration a case is, for the properties' statistics (judging/features.h).
struct Features {
  bool touching = false;    // in contract, and the exact margin is 0 with a hit
  bool parallel = false;    // see parallel_applies()
  bool degenerate = false;  // zero extent, zero radius, zero direction, a degenerate triangle...
};

/// How a kind's answers are judged against the exact one (judging/classify.h).
enum class Judged {
  hit,         // the hit, and its parameters where it gives any (ray t, contact times)
  all_pairs,   // every pair listed by one and not the other, each at its own margin
  first_pair,  // the pair named must be an exact one; a miss leaves only pairs within the band
  frames,      // every pair of every frame
  corners,     // the hit, then the corners it gives (params: x, y, z of each) against the exact ones
};

/// One term of a certified error bound that the kind's cases measure (judging/bound_coverage.h):
/// the library's test, the quantity it certifies, the term ("total": the whole bound).
struct BoundTerm {
  std::string_view test, quantity, term;
};

/// A kind's unit: Query<its input type> specialised in the kind's header.
template <class In>
struct Query;

/// The pieces a unit may leave as they are here.
struct QueryDefaults {
  static constexpr Judged judged = Judged::hit;
  /// A case builds hierarchies (about 30 ms): tests and commands run fewer of them.
  static constexpr bool builds_hierarchies = false;
  /// Whether "parallel" means something for the kind (judging/features.h).
  static constexpr bool parallel_applies = true;
};

/// What every unit provides (Query<In>, for an input type In):
///   band                  the library's tolerance band for the kind (model/band.h)
///   relations             the metamorphic relations that apply (judging/relation.h)
///   judged                how its answers are judged
///   ask(in)               the library's answer
///   generate(values, o)   a case drawn toward the decision boundary (generation/generate.h)
///   touch(in, values)     the second shape moved to touch the first by construction
///   features(in)          whether it is parallel or degenerate (judging/features.h)
///   configurations()      the configurations its generator is meant to make, and
///   recognise(in, found)  which of them a case is in (judging/configurations.h)
///   bound_terms()         the error-bound terms its cases measure, and
///   probe(in, records)    the library's certified quantities on a case (judging/bound_coverage.h)
/// and may provide:
///   library_parties()     the library's other ways to answer, each a Party judged by `band`
///   admits(in, relation)  false where a relation of `relations` does not hold for this input
template <class In>
concept QueryUnit = requires(const In& in, In& moved, ValueSource& values, const GenerateOptions& options,
                             Configurations& found, std::vector<bounds::Records>& records) {
  requires std::same_as<std::remove_cv_t<decltype(Query<In>::band)>, Band>;
  requires std::same_as<std::remove_cv_t<decltype(Query<In>::relations)>, Relations>;
  requires std::same_as<std::remove_cv_t<decltype(Query<In>::judged)>, Judged>;
  requires std::same_as<std::remove_cv_t<decltype(Query<In>::builds_hierarchies)>, bool>;
  requires std::same_as<std::remove_cv_t<decltype(Query<In>::parallel_applies)>, bool>;
  { Query<In>::ask(in) } -> std::same_as<Answer>;
  { Query<In>::generate(values, options) } -> std::same_as<In>;
  { Query<In>::touch(moved, values) } -> std::same_as<void>;
  { Query<In>::features(in) } -> std::same_as<Features>;
  { Query<In>::configurations() } -> std::same_as<std::span<const std::string_view>>;
  { Query<In>::recognise(in, found) } -> std::same_as<void>;
  { Query<In>::bound_terms() } -> std::same_as<std::span<const BoundTerm>>;
  { Query<In>::probe(in, records) } -> std::same_as<void>;
  requires HasFields<In>;
};

}  // namespace cc::harness
