// Boxes for the generators (shapes.cpp): axis-aligned and oriented, points of their boundary,
// pairs of oriented boxes in the regimes of the box tests' bounds.
#pragma once

#include <utility>
#include <vector>

#include "collide/aabb.h"
#include "collide/obb.h"
#include "harness/generation/generate.h"
#include "harness/generation/values.h"

namespace cc::harness {

/// A box [lo, lo + extent], extents often 0; out of contract sometimes inverted.
Aabb draw_aabb(ValueSource& values, const GenerateOptions& options);
/// A point of the box's boundary: a corner, a point on an edge or on a face.
Vec3 draw_boundary_point(ValueSource& values, const Aabb& box);
/// An OBB with a rotation from draw_rotation (or, out of contract, a non-orthonormal one).
Obb draw_obb(ValueSource& values, const GenerateOptions& options);

/// Two oriented boxes.
struct ObbPair {
  Obb a, b;
};
/// Two boxes with a common centre in the regimes of test_obb_obb's bound: aspect ratios up to
/// 2^40, sizes up to 2^40 apart, far from the origin, frames at the orthonormality tolerance or
/// nearly parallel.
ObbPair obb_pair_in_regime(ValueSource& values);
/// A direction to slide b along: a face normal of either box, an edge-edge axis, or any.
Vec3 slide_direction(ValueSource& values, const Obb& a, const Obb& b);
/// The half width of the box's projection onto w (w not normalised).
double reach_along(const Obb& box, const Vec3& w);

/// The items in any order (the constructions build them in a fixed one).
template <class T>
void shuffle(Choices& choices, std::vector<T>& items) {
  for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[choices.draw(i)]);
}

}  // namespace cc::harness
