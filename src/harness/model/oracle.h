// The harness reaches the oracles only through these interfaces; oracle/ implements them.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "harness/model/answer.h"
#include "harness/model/explanation.h"
#include "harness/model/input.h"

namespace cc::bounds {
struct Records;  // collide/bound_records.h
}  // namespace cc::bounds

namespace cc::harness {

/// Whether a query's inputs lie in the library's documented domain.
enum class Contract {
  in,           // in the domain: the library's band applies
  documented,   // outside it, but the library documents its answer (NaN gives false, ...)
  unspecified,  // outside it, and the library only promises not to crash
};

/// A distance answer to check (ExactVerdict::check_distance): the signed distance (< 0: minus
/// the penetration depth), a point on each shape where the answer gives them (`witnessed`), and
/// the tolerances it is judged with.
struct DistanceClaim {
  double distance = 0;
  bool witnessed = false;
  Vec3 on_a, on_b;
  double distance_tolerance = 0, point_tolerance = 0;
};

/// A pair of triangles of two meshes and its exact margin (as ExactVerdict::margin).
struct PairMargin {
  FacePair pair;
  double margin = 0;
  friend bool operator==(const PairMargin&, const PairMargin&) = default;
};

/// The exact reference's verdict on one query.
struct ExactVerdict {
  Contract contract = Contract::in;
  bool decided = true;  // false: the reference cannot decide this input ("undecided")
  Answer answer;        // the exact answer, or the documented one out of contract
  /// How far the case is from the decision boundary, relative to the inputs' scale: > 0 the
  /// shapes overlap by that much, < 0 they are apart by that much, 0 they touch. NaN when
  /// there is no such measure (out of contract).
  double margin = 0;
  std::string note;  // why out of contract or undecided
  /// Mesh queries: the margin of every pair of triangles that collides or nearly does, sorted
  /// by pair; `margin` is the one nearest 0. A pair not listed is apart by more than
  /// -unlisted_margin of the scale (their bounding boxes are), and counts as at that margin.
  std::vector<PairMargin> pair_margins;
  double unlisted_margin = 0;
  /// When not empty: the closed range [first, second] in which each parameter of a hit must
  /// lie to be right (instead of the band's relative width), e.g. a first contact time no
  /// later than the exact one and no earlier than the band allows.
  std::vector<std::pair<double, double>> param_ranges;
  /// Corners of an intersection (Judged::corners): answer.params holds the exact corners (x, y, z
  /// of each, rounded to nearest), and the hull of a party's corners must lie within this distance
  /// of theirs, and theirs within it of the hull (Hausdorff distance).
  double corner_tolerance = 0;
  /// Distances (Judged::distance): answer.params holds the exact signed distance (the distance
  /// apart, or minus the penetration depth), rounded (toward zero where it is a bare root);
  /// `scale` is the inputs' largest magnitude, which a second opinion's band is relative to; and
  /// check_distance(claim) decides in exact arithmetic whether an answer is right: the distance
  /// within distance_tolerance of the exact one and, where the answer gives points, each within
  /// point_tolerance of its shape's boundary and the two as far apart as the distance says,
  /// within distance_tolerance + 2 point_tolerance. Nothing when right, else why not. Empty for
  /// the other kinds.
  double scale = 0;
  std::function<std::optional<std::string>(const DistanceClaim& claim)> check_distance;

  /// The margin of a pair of a mesh query.
  double margin_of(const FacePair& pair) const;
};

/// How far one certified quantity of the library was from its exact value, against one term of
/// the bound the library certified it with (see bound_coverage.h).
struct TermError {
  std::string_view family;  // the kind of quantity, e.g. "slab parameter", "axis"
  std::string_view term;    // a term of its bound, or "total": the whole bound, slack included
  double error = 0;         // the actual error of what the term covers (>= 0; inf: a bound failed)
  double bound = 0;         // the term's value
  /// Whether the quantity is at its decision: its exact value (a gap, a difference of squares,
  /// a determinant) within a few times its bound of the threshold, or an extreme point of what
  /// it bounds. Only there can an error decide an answer. (Quantities with no threshold of their
  /// own are at the case's decision: true.)
  bool decisive = true;
};

class ExactReference {
 public:
  virtual ~ExactReference() = default;
  virtual ExactVerdict judge(const Input& input) const = 0;
  /// The reasoning behind judge(), for triage. Out of contract inputs get what can be shown.
  virtual Explanation explain(const Input& input) const = 0;
  /// For every certified quantity in `records` (what the library's probed tests computed, see
  /// collide/bound_records.h), the actual error of what each term of its bound covers.
  virtual std::vector<TermError> bound_errors(const bounds::Records& records) const = 0;
};

/// A second-opinion party as its oracle declares it: its name and its band.
struct PartyBand {
  std::string party;
  Band band;
};

class SecondOpinion {
 public:
  virtual ~SecondOpinion() = default;
  /// One opinion per party that covers this kind of query (possibly "not applicable"), each
  /// with its party's name and band.
  virtual std::vector<Opinion> opinions(const Input& input) const = 0;
  /// The parties that answer this kind of query, with their bands, in the order of opinions().
  virtual std::vector<PartyBand> parties(QueryKind kind) const = 0;
  /// How many opinions this process has cut short by a jump out of a party's code (a time
  /// limit, or an abort() caught). What that code held is leaked and the heap may be left
  /// inconsistent: a process that goes on to other cases after one should be replaced.
  virtual int abandoned_calls() const { return 0; }
};

}  // namespace cc::harness
