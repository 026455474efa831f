#include "collide/box_features.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace cc {

std::array<Vec3, 8> corners(const Obb& box) {
  const Vec3 e[3] = {box.half.x * box.axes.col[0], box.half.y * box.axes.col[1], box.half.z * box.axes.col[2]};
  std::array<Vec3, 8> out;
  for (int i = 0; i < 4; ++i) {  // corner i and its opposite, 7 - i
    const Vec3 offset = ((i & 1 ? e[0] : -e[0]) + (i & 2 ? e[1] : -e[1])) - e[2];
    out[i] = box.center + offset;
    out[7 - i] = box.center - offset;
  }
  return out;
}

int farthest_feature(const Obb& box, const Vec3& n, double tolerance, const Vec3& shift, Triangle out[2]) {
  const std::array<Vec3, 8> corner = corners(box);  // bit k of an index set for +half_k
  int bits = 0, free[3], free_count = 0, largest = 0;
  double along[3];
  for (int k = 0; k < 3; ++k) {
    along[k] = dot(box.axes.col[k], n);
    if (std::fabs(along[k]) > std::fabs(along[largest])) largest = k;
  }
  for (int k = 0; k < 3; ++k) {
    if (k != largest && std::fabs(along[k]) <= tolerance) {
      free[free_count++] = k;
    } else if (along[k] > 0) {
      bits |= 1 << k;
    }
  }
  const auto at = [&](int extra) { return corner[bits | extra] + shift; };
  if (free_count == 0) {
    const Vec3 p = at(0);
    out[0] = {{p, p, p}};
    return 1;
  }
  const int e1 = 1 << free[0];
  if (free_count == 1) {
    const Vec3 p = at(0), q = at(e1);
    out[0] = {{p, q, q}};
    return 1;
  }
  const int e2 = 1 << free[1];
  const Vec3 p00 = at(0), p10 = at(e1), p11 = at(e1 | e2), p01 = at(e2);
  out[0] = {{p00, p10, p11}};
  out[1] = {{p00, p11, p01}};
  return 2;
}

}  // namespace cc
