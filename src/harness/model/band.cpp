#include "harness/model/band.h"

#include <cmath>

namespace cc::harness {

bool within_band(const Band& band, bool says_hit, double margin) {
  if (std::isnan(margin)) return false;
  switch (band.sides) {
    case BandSides::exact: return false;
    case BandSides::conservative: return says_hit && margin <= 0 && -margin <= band.width;
    case BandSides::two_sided: return std::fabs(margin) <= band.width;
  }
  return false;
}

std::string_view to_string(BandSides sides) {
  switch (sides) {
    case BandSides::exact: return "exact";
    case BandSides::conservative: return "conservative";
    case BandSides::two_sided: return "two-sided";
  }
  return "?";
}

}  // namespace cc::harness
