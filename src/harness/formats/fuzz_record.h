// The fixed-layout binary record a fuzz target reads from the front of its input, so that a
// dictionary entry and a hex dump line up with fields:
//
//   byte 0      tag: bits 0-3 the query kind's number (informative), bits 4-7 flags
//   (kdop_kdop) byte 1: k (index into 6 14 16 18 24 26, modulo 6), byte 2: points in a (1 + b % 8),
//               byte 3: points in b (1 + b % 8)
//   (mesh_*)    byte 1: triangles of a (1 + b % 4), byte 2: triangles of b (1 + b % 4), byte 3: the
//               rotation of b's pose (table_rotation(b % 32); a's pose is the identity), byte 4:
//               the library's hierarchy (bits 0-2 bv type, 3-4 build strategy % 3, 5 exact
//               update, 6 larger-first descent)
//   (broadphase) byte 1: boxes (1 + b % 8), byte 2: frames (1 + b % 4), bytes 3-6: per frame a
//               mask of the boxes present (bit i: box i)
//   (ray_mesh)  byte 1: triangles (1 + b % 4), byte 2: the library's hierarchy (as mesh_*)
//   then        little-endian IEEE doubles, in the order of the kind's fields (below)
//
// Fields: ray_aabb origin, dir, tmin, tmax, lo, hi (flag bit 4: tmin = -inf, bit 5: tmax = +inf);
// sphere_sphere a.center, a.radius, b.center, b.radius; aabb_aabb a.lo, a.hi, b.lo, b.hi;
// kdop_kdop the points of a, then of b; obb_obb a.center, a.half, a.axes (by columns), the same
// for b; tri_aabb the 3 vertices, lo, hi; tri_obb the 3 vertices, center, half, axes; tri_tri
// the 3 vertices of a, then of b; mesh_* b's translation, then the triangles of a, then of b
// (small soups; a rotation not in the table is recorded as the identity); broadphase lo, hi of
// every box of every frame (absent ones too, ignored); ray_mesh origin, dir, tmin, tmax (flags as
// ray_aabb), then the triangles; moving_obb a as obb_obb, a's velocity, then b the same. A
// shorter input reads as if padded with zero bytes.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "harness/model/input.h"

namespace cc::harness {

/// The record's bytes for an input.
std::vector<std::uint8_t> encode_record(const Input& input);

/// The input a record describes, for a given kind (the tag's kind bits are not checked).
Input decode_record(QueryKind kind, std::span<const std::uint8_t> bytes);

/// The doubles of an input in record order, and back (same kind and shape: k and point counts).
std::vector<double> record_values(const Input& input);
Input with_record_values(const Input& shape, std::span<const double> values);

}  // namespace cc::harness
