// The fixed-layout binary record a fuzz target reads from the front of its input, so that a
// dictionary entry and a hex dump line up with fields:
//
//   byte 0      the tag: bits 0-3 the query kind's number (informative), bits 4-7 flags
//   then        the header bytes of the kind's fields, in the order of its fields
//   then        little-endian IEEE doubles: the values of its fields, in the same order
//
// The kind's fields (Fields<its input>, in its unit) decide the order; each part contributes:
//   a double, a point, a triangle    1, 3, 9 values; a box's axes 9 values, by columns; a point
//                                    of the plane 2 values
//   a box, a sphere, a moving box,   its fields' values (lo, hi; center, radius; center, half,
//   a disc, a wall                   axes, velocity; center, radius; a, b)
//   a ray                            origin, dir, tmin, tmax; flags: bit 4 tmin = -inf, bit 5
//                                    tmax = +inf
//   k of a k-DOP                     a header byte: an index into 6 14 16 18 24 26 (modulo 6)
//   a point set                      a header byte (1 + b % 8 points), then the points
//   a list of parts (walls)          a header byte (1 + b % 8 parts), then each part's values
//   a mesh                           a header byte (a soup of 1 + b % 4 triangles), then their vertices
//   the library's hierarchy          a header byte: bits 0-2 the volume type, 3-4 the build
//                                    strategy % 3, 5 the exact update, 6 larger-first descent
//   two placed meshes                four header bytes (triangles of a, of b, b's rotation as
//                                    table_rotation(b % 32), the hierarchy), then b's translation,
//                                    the soup of a, the soup of b; a's pose is the identity (a
//                                    rotation not in the table is recorded as the identity)
//   boxes over frames                six header bytes (1 + b % 8 boxes, 1 + b % 4 frames, per frame
//                                    a mask of the boxes present, bit i for box i), then lo and hi
//                                    of every box of every frame (absent ones too, ignored)
// A shorter input reads as if padded with zero bytes.
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

/// The doubles of an input in record order, and back: the input of the same kind and shape as
/// `shape` (as its record has it: k, point and triangle counts, meshes as soups, frames) with
/// these values.
std::vector<double> record_values(const Input& input);
Input with_record_values(const Input& shape, std::span<const double> values);

}  // namespace cc::harness
