// Why the exact reference decides a case as it does, for `crosscheck triage` and its drawing:
// a table (every separating axis with both projections and the gap in exact and in floating
// point; every slab of a ray; every slab of a k-DOP), a few named facts, and the deciding
// quantity with its size in ULPs.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "collide/vec3.h"

namespace cc::harness {

struct Explanation {
  std::string title;                           // e.g. "separating axes"
  std::vector<std::string> columns;            // the table's header
  std::vector<std::vector<std::string>> rows;  // one per axis or slab
  int deciding_row = -1;                       // the row that decides, if any
  std::vector<std::pair<std::string, std::string>> facts;
  std::string deciding;                        // what decides, in words
  double deciding_value = 0;                   // the deciding quantity (exact, rounded)
  double deciding_ulps = 0;                    // that quantity in ULPs of its magnitude
  // For drawing: the deciding direction and both projected intervals on it, when there is one.
  std::optional<Vec3> axis;
  double a_lo = 0, a_hi = 0, b_lo = 0, b_hi = 0;
};

}  // namespace cc::harness
