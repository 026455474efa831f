// Each query kind's pieces, as the layers below the kinds reach them: a table per kind, filled by
// kinds/pieces.cpp from the kind's unit (Query<In>, kinds/query.h). Generating, touching,
// judging, shrinking and the library's answer all dispatch through it, so none of them includes
// a kind; the kinds, at the top of the harness, include what they build on.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "harness/model/answer.h"
#include "harness/model/band.h"
#include "harness/model/input.h"
#include "harness/model/relation.h"

namespace cc::bounds {
struct Records;  // collide/bound_records.h
}  // namespace cc::bounds

namespace cc::harness {

class ValueSource;       // generation/values.h
struct GenerateOptions;  // generation/generate.h
class Configurations;    // judging/configurations.h

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
  distance,    // the signed distance and a closest pair (params: d, then x, y, z of a point of a,
               // of b; or d alone), within the bounds the party certifies (params 8 and 9:
               // distance and point error) or else its band, relative to the inputs' scale
               // (ExactVerdict::check_distance)
};

/// One term of a certified error bound that the kind's cases measure (judging/bound_coverage.h):
/// the library's test, the quantity it certifies, the term ("total": the whole bound).
struct BoundTerm {
  std::string_view test, quantity, term;
};

/// A kind's pieces (what each means: kinds/query.h). The functions taking an Input take one of
/// this kind (any other is a programming error: std::bad_variant_access).
struct KindPieces {
  Band band;
  Relations relations = {};
  Judged judged = Judged::hit;
  bool builds_hierarchies = false;
  bool parallel_applies = true;
  Answer (*ask)(const Input& in) = nullptr;
  /// The library's other ways to answer (its parties, each judged by `band`); none for most kinds.
  std::vector<Opinion> (*library_alternatives)(const Input& in) = nullptr;
  Input (*generate)(ValueSource& values, const GenerateOptions& options) = nullptr;
  void (*touch)(Input& in, ValueSource& values) = nullptr;
  Features (*features)(const Input& in) = nullptr;
  std::span<const std::string_view> (*configurations)() = nullptr;
  void (*recognise)(const Input& in, Configurations& found) = nullptr;
  std::span<const BoundTerm> (*bound_terms)() = nullptr;
  void (*probe)(const Input& in, std::vector<bounds::Records>& records) = nullptr;
  /// False where a relation of `relations` does not hold for this input.
  bool (*admits)(const Input& in, Relation relation) = nullptr;
};

/// The pieces of a kind (defined with the kinds, in kinds/pieces.cpp).
const KindPieces& pieces_of(QueryKind kind);

}  // namespace cc::harness
