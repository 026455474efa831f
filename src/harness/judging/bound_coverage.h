// How close the library's actual rounding comes to each term of its certified error bounds, over
// generated cases. Each case's certified quantities are recorded by the library's probed tests
// (collide/bound_records.h), the exact reference measures the error that each term covers
// (ExactReference::bound_errors), and the table keeps per term the closest approach: the largest
// error / term met. A term never approached within kApproachFactor is a term no case needs, so
// no case checks it; an error beyond a bound's total is a bound that does not hold.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "collide/record_sink.h"
#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::harness {

/// How close a case must come to a term for the term to count as approached.
inline constexpr double kApproachFactor = 0x1p-8;

/// A term's approach counts only on cases this near the decision boundary (the exact margin,
/// relative to the inputs' scale, at most this in magnitude: beyond every band), and on the
/// quantities there that are at their own decision (TermError::decisive): elsewhere no error
/// of that size could change an answer.
inline constexpr double kNearBoundary = 0x1p-30;

/// The library's certified quantities on one case, as its probed tests record them: one
/// Records per call that stands alone (two placed meshes are measured apart). Nothing for kinds
/// without a certified bound (those that compare their inputs). The kind's unit probes.
std::vector<bounds::Records> probe_library(const Input& input);

/// One term of one bound, as measured: a row of `crosscheck bounds`.
struct TermCoverage {
  std::string test;      // the library's test, e.g. "test_obb_obb"
  std::string quantity;  // what it certifies, e.g. "axis" (ExactReference's family)
  std::string term;      // a term of the bound, or "total" (the whole bound)
  double closest = 0;    // the closest approach: the largest error / term at a decision (0: none)
  long quantities = 0;   // quantities at their decision (a total: every one)
  long cases = 0;        // cases that had one
  double largest = 0;    // the largest error / term anywhere: above 1, the term does not hold
  std::string closest_case, largest_case;  // the inputs (JSON) of the cases that gave them

  /// A term: approached within kApproachFactor, and never exceeded. A total: never exceeded.
  bool ok() const;
};

/// The rows every complete measurement has: each term of each certified test's bound, and each
/// total, with the query kind whose cases measure it (each kind's unit names its terms,
/// Query<In>::bound_terms; a term two kinds measure is listed for each).
struct ExpectedTerm {
  QueryKind kind;
  std::string_view test, quantity, term;
};
std::span<const ExpectedTerm> expected_terms();

/// What one case added to the table.
struct CaseCoverage {
  bool measured = false;  // in the library's domain (others are skipped)
  double largest = 0;     // its largest error / term (or / total): above 1, a bound fails on it
  std::string where;      // the test, quantity and term of that
};

/// The coverage table over the cases added so far.
class BoundCoverage {
 public:
  /// Measures one case.
  CaseCoverage add(const Input& input, const ExactReference& exact);
  /// Every expected row of the kinds given (all when empty), measured or not, then any other.
  std::vector<TermCoverage> rows(std::span<const QueryKind> kinds = {}) const;

 private:
  std::vector<TermCoverage> rows_;
};

/// The test a quantity of a query kind's case belongs to, by the kind's terms (a moving box's
/// "aabb time" is sweep_aabb_aabb's); the kind's name when none says.
std::string_view test_of(QueryKind kind, std::string_view quantity);

/// The table as text, one row per line: test, quantity, term, closest approach (as a power of
/// two), quantities, cases, and what is wrong with it.
std::string format_coverage(const std::vector<TermCoverage>& rows);

}  // namespace cc::harness
