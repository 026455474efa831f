// A tolerance band: how far from the decision boundary a party may disagree with the exact
// answer and still count as right. Each is declared once, with what it belongs to: the library's
// per kind in the kind's unit (src/harness/kinds/<kind>.h), a second opinion's with its call in
// the oracle's unit for the kind (oracle/fcl/kinds/<kind>.cpp). A band is never widened to make
// a case pass.
#pragma once

#include <string_view>

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

/// Whether a disagreement lies inside the band: `says_hit` is what the party answered, `margin`
/// the exact margin (> 0 overlapping, < 0 apart).
bool within_band(const Band& band, bool says_hit, double margin);

std::string_view to_string(BandSides sides);

}  // namespace cc::harness
