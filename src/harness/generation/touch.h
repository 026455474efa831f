// Constructions that bring two shapes into contact, exactly when the values allow (simple
// values, exactly orthonormal frames) and otherwise within a few ULPs. The generators and the
// fuzzers' custom mutator both use them; each kind's unit says how its shapes touch
// (Query<In>::touch), with the constructions below.
#pragma once

#include "harness/generation/values.h"
#include "harness/model/input.h"

namespace cc::harness {

/// Moves the second shape (the ray, the triangle against a box) so that it touches the first.
void make_touching(Input& input, ValueSource& values);

/// Mesh b translated so that one of its vertices lands on one of a's: within the roundings of
/// the two vertices placed and of their difference, whatever b's translation was before (exactly
/// where those are exact).
void touch_at_vertices(MeshPair& m, Choices& choices);

/// B moved so that its corner farthest against the normal of a face of A (on a tie, either)
/// lands on a point of that face (its centre, a point halfway to an edge, on an edge, a corner):
/// B touches A there, within the rounding of the moves. With `nudged`, a few ULPs of the reach
/// off along the normal, into A or away from it.
void place_against_face(const Obb& a, Obb& b, ValueSource& values, bool nudged);

/// B (its extents kept) moved against a face of A on one axis, above or below, and onto A's
/// range on the other two where it misses it: the boxes touch, exactly.
void put_face_to_face(const Aabb& a, Aabb& b, Choices& choices);

/// The triangle moved so that its vertex i lands exactly on p.
void put_vertex_at(Triangle& t, int i, const Vec3& p);

}  // namespace cc::harness
