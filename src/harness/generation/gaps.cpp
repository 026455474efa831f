#include "harness/generation/gaps.h"

#include <algorithm>
#include <cmath>


namespace cc::harness {

double draw_gap(Choices& c) {
  switch (c.draw(3)) {
    case 0: return 0;
    case 1: return std::ldexp(1.0, -static_cast<int>(c.draw(61)));
    default: return -std::ldexp(1.0, -static_cast<int>(c.draw(61)));
  }
}

void scale_by_a_power_of_two(Choices& c, std::initializer_list<double*> values) {
  const int e = static_cast<int>(c.draw(601)) - 300;
  // An infinity leaves every value as it is (not within 2^500); all zero: the smallest stays
  // infinite, and any scale does.
  double largest = 0, smallest = INFINITY;
  for (const double* x : values) {
    const double m = std::fabs(*x);
    largest = std::max(largest, m);
    if (m > 0) smallest = std::min(smallest, m);
  }
  if (!(std::ldexp(largest, e) <= 0x1p500) || std::ldexp(smallest, e) < 0x1p-1000) return;
  for (double* x : values) *x = std::ldexp(*x, e);
}

}  // namespace cc::harness
