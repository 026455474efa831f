// The regimes the library's certified error bounds cover, for the generators' bound-reaching
// constructions (regimes.cpp): sizes, aspect ratios up to 2^40, translations far beyond the
// shapes' size, frames at the orthonormality tolerance, nearly parallel frames, and the exact
// margin a construction is placed at.
#pragma once

#include "collide/vec3.h"
#include "harness/generation/generate.h"
#include "harness/generation/margin_bisection.h"
#include "harness/generation/values.h"

namespace cc::harness {

/// A length: 2^k for k in [-20, 20], or a generic multiple of one.
double draw_size(ValueSource& values);
/// Half extents with aspect ratios up to 2^40 (size on some axes, down to size 2^-40 on
/// others), sometimes 0 (flat boxes, segments, points).
Vec3 draw_aspect_extents(ValueSource& values, double size);
/// A generic direction, not normalised, never zero: each component 0 or of magnitude in
/// [2^-3, 2).
Vec3 draw_direction(ValueSource& values);
/// A translation up to 2^40 times `size` in a generic direction (or none).
Vec3 draw_far_offset(ValueSource& values, double size);
/// Whether the matrix's axes are orthonormal to within kObbOrthonormalTolerance, checked in
/// floating point with room for that check's rounding.
bool within_tolerance(const Mat3& m);
/// The rotation with its axes moved off orthonormal by 0.5 to 0.7 of kObbOrthonormalTolerance
/// (every entry of the Gram matrix), inside the tolerance.
Mat3 perturb_to_tolerance(ValueSource& values, const Mat3& rotation);
/// `base` turned by an angle of 2^-8 to 2^-52 about a generic axis: nearly parallel axes.
Mat3 nearly_parallel(ValueSource& values, const Mat3& base);

/// Where a bound-reaching construction is placed: an exact margin (ExactVerdict units) and the
/// side of it. Mostly touching (0, either side), else apart or overlapping by 2^-40 to 2^-53 of
/// the scale: a small multiple of the library's error bounds, both signs.
struct MarginTarget {
  double margin;
  Side side;
};
MarginTarget draw_margin_target(Choices& choices);

/// The parameter of `family` at the target margin, from a case that overlaps (s_overlap) and one
/// that is apart (s_apart), by exact bisection with options.exact; `fallback` without it or when
/// no crossing is found.
double place_at(const Family& family, double s_overlap, double s_apart, const MarginTarget& target,
                const GenerateOptions& options, double fallback);

}  // namespace cc::harness
