// What the tests of intersect_triangles against the exact intersection share: a pair written
// exactly for a failure's message, and the distance of the library's points from the exact ones
// with the bound triangle_intersection.h documents for it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "collide/triangle_intersection.h"
#include "oracle/exact/exact_triangle_intersection.h"
#include "oracle/exact/rational.h"

namespace cc::test {

/// Both triangles' vertices as hex floats, "(x, y, z) ... | ... | ".
inline std::string describe(const Triangle& a, const Triangle& b) {
  std::string s;
  char buf[96];
  for (const Triangle* t : {&a, &b}) {
    for (const Vec3& p : t->v) {
      std::snprintf(buf, sizeof buf, "(%a, %a, %a) ", p.x, p.y, p.z);
      s += buf;
    }
    s += "| ";
  }
  return s;
}

/// Exact points, rounded, for a message.
inline std::string points_text(const std::vector<exact::QVec3>& points) {
  std::string s;
  char buf[96];
  for (const exact::QVec3& q : points) {
    const Vec3 p = exact::to_double(q);
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g) ", p.x, p.y, p.z);
    s += buf;
  }
  return s;
}

/// The Hausdorff distance between the hull of the library's points and the exact one, both ways
/// (rounded once, at the end), and its bound 2^-44 M kappa + 2^-1074 (M the pair's largest
/// coordinate, kappa the corners' largest condition number, at least 1).
struct CornerDistance {
  double distance = 0, bound = 0, kappa = 1;
  std::vector<exact::QVec3> said, truth;
};

inline CornerDistance corner_distance(const Triangle& a, const Triangle& b, const TriangleIntersection& r,
                                      const std::vector<exact::ExactCorner>& corners) {
  CornerDistance d;
  double m = 0;
  for (const Triangle* t : {&a, &b}) {
    for (const Vec3& p : t->v) m = std::max(m, max_abs(p));
  }
  for (const auto& c : corners) d.truth.push_back(c.point), d.kappa = std::max(d.kappa, c.condition);
  for (int i = 0; i < r.count; ++i) d.said.push_back(exact::rational(r.points[i]));
  exact::Rational worst = 0;
  for (const exact::QVec3& p : d.said) worst = std::max(worst, exact::distance2_to_hull(p, d.truth));
  for (const exact::QVec3& p : d.truth) worst = std::max(worst, exact::distance2_to_hull(p, d.said));
  d.distance = std::sqrt(exact::to_double(worst));
  d.bound = 0x1p-44 * m * d.kappa + 0x1p-1074;
  return d;
}

}  // namespace cc::test
