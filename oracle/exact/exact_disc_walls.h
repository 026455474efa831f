// The maze's exact reference: a disc against a wall segment in rational arithmetic (the closest
// point of the segment by the clamped projection parameter, and its squared distance).
#pragma once

#include "collide/disc_walls.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

struct ExactDiscWall {
  bool touches = false;    // |centre - segment| <= radius
  Rational distance2;      // |centre - segment|^2
  Rational slack;          // radius^2 - distance2: > 0 overlapping, 0 touching, < 0 apart
  bool pillar = false;     // the wall's ends are equal
  Rational t;              // the nearest point a + t (b - a), t clamped to [0, 1] (0 for a pillar)
  double scale = 0;        // the largest |coordinate| of the centre and the wall, or the radius
  /// (radius - distance) / scale, rounded, with the exact sign (> 0 overlapping, 0 touching,
  /// < 0 apart; a scale of 0 counts as 1).
  double margin = 0;
};

/// Finite inputs and a radius >= 0 (the library's domain, without its magnitude limit).
ExactDiscWall exact_disc_wall(const Disc& disc, const Wall& wall);

/// Whether `says_touch` is right for this disc and wall, allowing a conservative answer: a
/// touch may be reported for a disc apart by at most `band` times the scale (exactly); a miss
/// is right only when the disc is apart.
bool disc_wall_answer_right(const ExactDiscWall& exact, const Disc& disc, bool says_touch, double band);

}  // namespace cc::exact
