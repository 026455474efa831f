// A ray (or segment) against a closed triangle in exact arithmetic: where it first meets it, and
// how far a point is from it. Complete for degenerate triangles, rays in the triangle's plane
// and a zero direction.
#pragma once

#include <array>
#include <optional>

#include "collide/ray.h"
#include "collide/triangle.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// origin + t dir for t in [tmin, tmax]; an absent bound is infinite.
struct ExactRay {
  QVec3 o, d;
  std::optional<Rational> tmin, tmax;

  bool in_range(const Rational& t) const { return (!tmin || t >= *tmin) && (!tmax || t <= *tmax); }
  QVec3 at(const Rational& t) const { return o + t * d; }
};

/// The ray as rationals (finite coordinates; tmin = -inf and tmax = +inf become absent bounds).
ExactRay exact_ray(const Ray& ray);
/// The triangle's vertices as rationals.
std::array<QVec3, 3> exact_triangle(const Triangle& t);

/// The smallest t in range at which the ray meets the closed triangle, if any. With a zero
/// direction the ray is its origin alone (then tmin must be finite).
std::optional<Rational> exact_first_hit(const ExactRay& r, const std::array<QVec3, 3>& v);

/// Whether p lies on the closed segment [a, b] (a point when a = b).
bool on_segment(const QVec3& p, const QVec3& a, const QVec3& b);

/// The squared Euclidean distance from p to the closed triangle (degenerate ones included).
Rational distance2_to_triangle(const QVec3& p, const std::array<QVec3, 3>& v);

}  // namespace cc::exact
