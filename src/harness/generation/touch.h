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

/// Mesh b translated so that one of its vertices lands on one of a's (exactly when both poses
/// are exact, as signed permutations with simple translations are; otherwise within the
/// transforms' rounding).
void touch_at_vertices(MeshPair& m, Choices& choices);

/// B's centre against a face of A: at A's half extent plus B's reach along A's face normal,
/// plus an offset within the face. With `nudged`, a few ULPs off.
void place_against_face(const Obb& a, Obb& b, ValueSource& values, bool nudged);

/// B (its extent kept) moved against a face of A on one axis, above or below.
void put_face_to_face(const Aabb& a, Aabb& b, Choices& choices);

/// The triangle moved so that its vertex i lands exactly on p.
void put_vertex_at(Triangle& t, int i, const Vec3& p);

}  // namespace cc::harness
