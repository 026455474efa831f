#include "collide/triangle_foot.h"

#include <algorithm>

#include "collide/length.h"

namespace cc {

bool foot_in_triangle(const Vec3& p, const Triangle& tri, Vec3& foot) {
  const Vec3 e1 = tri.v[1] - tri.v[0], e2 = tri.v[2] - tri.v[0], w = p - tri.v[0];
  const double m = std::max({max_abs(e1), max_abs(e2), max_abs(w)});
  if (!(m > 0)) return false;
  const int e = fp::exponent_of(m);
  const Vec3 se1 = scaled(e1, e), se2 = scaled(e2, e), sw = scaled(w, e);
  const Vec3 n = cross(se1, se2);
  const double nn = dot(n, n);
  if (!(nn > 0)) return false;
  // The coordinates of w's part in the plane (w less its part along n): the far part of w is
  // taken away along n first, so that the coordinates are measured on the foot, near t.
  const Vec3 in_plane = sw - (dot(sw, n) / nn) * n;
  const double s = dot(cross(in_plane, se2), n) / nn, t = dot(cross(se1, in_plane), n) / nn;
  if (!(s >= 0 && t >= 0 && s + t <= 1)) return false;
  foot = tri.v[0] + s * e1 + t * e2;
  return true;
}

}  // namespace cc
