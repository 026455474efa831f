// What a party says about one query.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "harness/model/band.h"

namespace cc::harness {

/// A pair of triangles of two meshes: (face of a, face of b).
using FacePair = std::pair<std::uint32_t, std::uint32_t>;

/// The answer to a query: whether the shapes meet, and for some kinds parameters of the contact
/// (a ray's t interval, contact times), pairs (the colliding triangles of two meshes, sorted; a
/// face a ray hits as (face, 0)) or the pairs of each frame (sorted, in `frames`; hit when some
/// frame has one). Each kind's unit says what its answer holds (Query<In>::ask).
struct Answer {
  /// A hit or a miss, with nothing more.
  static Answer of(bool hit) {
    Answer a;
    a.hit = hit;
    return a;
  }
  bool hit = false;
  std::vector<double> params;
  std::vector<FacePair> pairs;
  std::vector<std::vector<FacePair>> frames;
  friend bool operator==(const Answer&, const Answer&) = default;
};

/// The answer of one party other than the library's own call (the library's other ways, a
/// second opinion) to one query.
struct Opinion {
  /// timed_out: cut off at its time limit. Whether a call returns in time depends on the
  /// machine and its load, so a time-out is never taken as an answer, and replay does not count
  /// a time-out on either side as a change.
  enum class Status { answered, not_applicable, failed, timed_out };
  std::string party;  // e.g. "fcl.OBBd::overlap"
  Status status = Status::not_applicable;
  Answer answer;
  std::string detail;  // why not applicable, or what failed
  /// The party's band, declared with it (model/party.h); case files do not store it, a party
  /// of today gives it.
  std::optional<Band> band = std::nullopt;
};

/// The start of the failure text of the library (or a subject) cut off at its time limit, which
/// replay takes as it takes an opinion's Status::timed_out.
inline constexpr std::string_view kTimedOut = "timed out";
inline bool is_time_out(std::string_view failure) { return failure.substr(0, kTimedOut.size()) == kTimedOut; }

}  // namespace cc::harness
