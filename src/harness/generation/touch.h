// Constructions that bring two shapes into contact, exactly when the values allow (simple
// values, exactly orthonormal frames) and otherwise within a few ULPs. The generators and the
// fuzzers' custom mutator both use them.
#pragma once

#include "harness/model/input.h"
#include "harness/generation/values.h"

namespace cc::harness {

/// Moves the second shape (the ray, the triangle against a box) so that it touches the first.
/// Meshes: b is translated so that one of its vertices meets one of a's.
void make_touching(Input& input, ValueSource& values);

/// Mesh b translated so that one of its vertices lands on one of a's (exactly when both poses
/// are exact, as signed permutations with simple translations are; otherwise within the
/// transforms' rounding).
void touch_at_vertices(MeshPair& m, Choices& choices);

/// B's centre against a face of A: at A's half extent plus B's reach along A's face normal,
/// plus an offset within the face. With `nudged`, a few ULPs off.
void place_against_face(ObbObbInput& in, ValueSource& values, bool nudged);

/// B's points shifted along one axis so that the k-DOPs touch on one slab.
void shift_to_touch(KdopKdopInput& in, ValueSource& values, bool nudged);

}  // namespace cc::harness
