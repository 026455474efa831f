// The named configurations the generators are meant to make, per query kind, each recognised
// from a case's inputs and its exact verdict (not from how the case was built): touching and
// nearly touching either way, parallel and nearly parallel frames, edges or rays, flat, segment
// and point shapes, shapes far from the origin compared with their size, aspect ratios past
// 2^20, frames at the orthonormality tolerance, rays from far away or with negative parameters,
// and so on. A property counts them over its cases and fails if one never appears: a generator
// that silently stops making a configuration is caught. Each kind's unit names its
// configurations and recognises them (Query<In>::configurations, recognise), with the
// recognisers kinds share below.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "harness/judging/shape_facts.h"
#include "harness/model/input.h"
#include "harness/model/oracle.h"

namespace cc::harness {

inline constexpr double kFar = 0x1p20;             // far from the origin, a long way, an aspect ratio
inline constexpr double kJust = 0x1p-40;           // an exact margin this small: nearly touching
inline constexpr double kAtTheTolerance = 0x1p-49;  // a Gram entry off by this: half the orthonormality tolerance

/// The configurations a case is in, as its kind recognises them.
class Configurations {
 public:
  explicit Configurations(const ExactVerdict& exact) : exact_(exact) {}

  const ExactVerdict& exact() const { return exact_; }
  /// Adds the configuration if `yes`.
  void add(std::string_view name, bool yes);
  /// "touching", "just apart", "just overlapping", by the exact margin (in contract, decided).
  void margins();
  /// "far from the origin": the largest coordinate at least 2^20 times the shapes' size.
  void far(double largest, double size);
  /// A box's "flat box", "segment box", "point box" (1, 2, 3 zero half extents), "long box".
  void boxes(const Vec3& half);
  /// A triangle's "segment triangle", "point triangle", "sliver" (longest edge over height 2^20).
  void triangle(const Triangle& t);
  /// A triangle against a box with the given axes (its centre at c): the triangle's, and "in a
  /// face's plane", "nearly in a face's plane", "edge nearly parallel to an axis", "far vertex
  /// not last".
  void triangle_and_box(const Triangle& t, const Mat3& axes, const Vec3& c);
  /// Two frames: "parallel axes", "nearly parallel axes", "frame at the tolerance".
  void axes_pair(const Mat3& a, const Mat3& b);
  /// "negative parameters": in contract, a hit whose first parameter is negative.
  void negative_parameters();

  std::vector<std::string_view> names;

 private:
  const ExactVerdict& exact_;
};

/// The vertex farthest from p is not the last.
bool far_vertex_not_last(const Triangle& t, const Vec3& p);

/// The configurations of expected_configurations(kind) that the case is in.
std::vector<std::string_view> configurations_of(const Input& input, const ExactVerdict& exact);

/// Every configuration the generators of a kind are meant to make.
std::span<const std::string_view> expected_configurations(QueryKind kind);

}  // namespace cc::harness
