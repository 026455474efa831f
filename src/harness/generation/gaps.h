// What the distance kinds' generators share (gaps.cpp): the signed gap a construction places its
// closest features at, and an exact scaling of a whole case by a power of two.
#pragma once

#include <initializer_list>

#include "harness/generation/choices.h"

namespace cc::harness {

/// A gap between closest features in units of their size: 0 (touching), 2^-k for k in [0, 60]
/// (apart by the size down to a few ULPs of it), or minus that (overlapping by as much).
double draw_gap(Choices& choices);

/// Every value times 2^e, e drawn in [-300, 300], when none leaves [2^-1000, 2^500] in magnitude
/// (0 stays 0): the scaling is then exact and the case stays in the distance queries' domain.
/// Values that are not lengths or coordinates (a box's axes) are not passed. Nothing changes when
/// a value would leave the range or is infinite; a NaN is not looked at (it stays NaN).
void scale_by_a_power_of_two(Choices& choices, std::initializer_list<double*> values);

}  // namespace cc::harness
