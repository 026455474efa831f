#include "oracle/exact/exact_ray_triangle.h"

#include <algorithm>
#include <cmath>

namespace cc::exact {
namespace {

bool in_triangle(const QVec3& p, const std::array<QVec3, 3>& v) {
  const QVec3 n = cross(v[1] - v[0], v[2] - v[0]);
  if (is_zero(n)) return on_segment(p, v[0], v[1]) || on_segment(p, v[1], v[2]) || on_segment(p, v[2], v[0]);
  if (sgn(dot(n, p - v[0])) != 0) return false;
  for (int i = 0; i < 3; ++i) {
    if (sgn(dot(n, cross(v[(i + 1) % 3] - v[i], p - v[i]))) < 0) return false;
  }
  return true;
}

// The first parameter at which the ray meets the segment [a, b].
std::optional<Rational> first_on_segment(const ExactRay& r, const QVec3& a, const QVec3& b) {
  const QVec3 e = b - a, w = a - r.o;
  if (is_zero(r.d)) return on_segment(r.o, a, b) ? r.tmin : std::nullopt;
  if (is_zero(e)) {
    if (!is_zero(cross(w, r.d))) return std::nullopt;
    const Rational t = dot(w, r.d) / dot(r.d, r.d);
    return r.in_range(t) ? std::optional(t) : std::nullopt;
  }
  const QVec3 m = cross(r.d, e);
  if (!is_zero(m)) {  // o + t d = a + s e
    if (sgn(dot(m, w)) != 0) return std::nullopt;  // skew
    const Rational mm = dot(m, m);
    const Rational t = dot(cross(w, e), m) / mm, s = dot(cross(w, r.d), m) / mm;
    return s >= 0 && s <= 1 && r.in_range(t) ? std::optional(t) : std::nullopt;
  }
  if (!is_zero(cross(w, r.d))) return std::nullopt;  // parallel lines apart
  const Rational dd = dot(r.d, r.d);
  Rational ta = dot(w, r.d) / dd, tb = dot(b - r.o, r.d) / dd;
  if (ta > tb) std::swap(ta, tb);
  const Rational lo = r.tmin ? std::max(ta, *r.tmin) : ta;
  const Rational hi = r.tmax ? std::min(tb, *r.tmax) : tb;
  return lo <= hi ? std::optional(lo) : std::nullopt;
}

Rational distance2_to_segment(const QVec3& p, const QVec3& a, const QVec3& b) {
  const QVec3 e = b - a, w = p - a;
  if (is_zero(e)) return dot(w, w);
  Rational s = dot(w, e) / dot(e, e);
  s = std::clamp(s, Rational(0), Rational(1));
  const QVec3 r = w - s * e;
  return dot(r, r);
}

}  // namespace

bool on_segment(const QVec3& p, const QVec3& a, const QVec3& b) {
  const QVec3 e = b - a, w = p - a;
  if (is_zero(e)) return is_zero(w);
  if (!is_zero(cross(w, e))) return false;
  const Rational s = dot(w, e);
  return s >= 0 && s <= dot(e, e);
}

ExactRay exact_ray(const Ray& ray) {
  ExactRay r{rational(ray.origin), rational(ray.dir), std::nullopt, std::nullopt};
  if (ray.tmin != -INFINITY) r.tmin = rational(ray.tmin);
  if (ray.tmax != INFINITY) r.tmax = rational(ray.tmax);
  return r;
}

std::array<QVec3, 3> exact_triangle(const Triangle& t) { return {rational(t.v[0]), rational(t.v[1]), rational(t.v[2])}; }

std::optional<Rational> exact_first_hit(const ExactRay& r, const std::array<QVec3, 3>& v) {
  const QVec3 n = cross(v[1] - v[0], v[2] - v[0]);
  if (!is_zero(n) && sgn(dot(n, r.d)) != 0) {  // crosses the plane once
    const Rational t = dot(n, v[0] - r.o) / dot(n, r.d);
    return r.in_range(t) && in_triangle(r.at(t), v) ? std::optional(t) : std::nullopt;
  }
  // In a plane with the triangle (or it is a segment or a point): the start or an edge.
  if (r.tmin && in_triangle(r.at(*r.tmin), v)) return r.tmin;
  std::optional<Rational> best;
  for (int i = 0; i < 3; ++i) {
    const auto t = first_on_segment(r, v[i], v[(i + 1) % 3]);
    if (t && (!best || *t < *best)) best = t;
  }
  return best;
}

Rational distance2_to_triangle(const QVec3& p, const std::array<QVec3, 3>& v) {
  Rational best = distance2_to_segment(p, v[0], v[1]);
  best = std::min(best, distance2_to_segment(p, v[1], v[2]));
  best = std::min(best, distance2_to_segment(p, v[2], v[0]));
  const QVec3 n = cross(v[1] - v[0], v[2] - v[0]);
  if (!is_zero(n)) {
    const Rational h = dot(n, p - v[0]), nn = dot(n, n);
    const Rational plane = h * h / nn;
    if (in_triangle(p - (h / nn) * n, v)) best = std::min(best, plane);
  }
  return best;
}

}  // namespace cc::exact
