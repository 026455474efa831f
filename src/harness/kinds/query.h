// What a query kind's unit provides to the harness: Query<its input type>, declared in
// src/harness/kinds/<kind>.h, defined in <kind>.cpp; its input and fields are in
// model/inputs/<kind>.h. The layers below reach a unit through the table of its pieces
// (model/kind_pieces.h), which kinds/pieces.cpp fills; a unit that lacks a piece does not compile
// (QueryUnit, checked there for every kind). The exact reference's and the second opinions'
// pieces of a kind are in oracle/exact/kinds/<kind>.cpp and oracle/<peer>/kinds/<kind>.cpp.
#pragma once

#include <concepts>
#include <span>
#include <string_view>
#include <vector>

#include "harness/model/answer.h"
#include "harness/model/band.h"
#include "harness/model/kind_pieces.h"
#include "harness/model/parts.h"
#include "harness/model/party.h"
#include "harness/model/relation.h"

namespace cc::harness {

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
///   relations             the metamorphic relations that apply (model/relation.h)
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
