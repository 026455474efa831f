#include "collide/obb.h"

#include "collide/bound_records.h"

namespace cc {
namespace {

template <class Records>
bool test(const Obb& a, const Obb& b, Records& records) {
  const Vec3 d = b.center - a.center;  // swapping a and b negates d exactly
  double r[3][3], abs_r[3][3];        // r[i][j] = a_i . b_j, row i computed before a_i is tried
  Vec3 ta;                            // d in a's frame, likewise

  // One bound for every axis: the rounding, and the axes' deviation from orthonormal (see
  // bounds::ObbBound).
  const double sum_a = fp::sum3(a.half.x, a.half.y, a.half.z);
  const double sum_b = fp::sum3(b.half.x, b.half.y, b.half.z);
  const bounds::ObbBound bound{norm1(d), sum_a, sum_b};
  records.add(bounds::ObbTest{{a, {}}, {b, {}}, bound});
  const double error = bound.total();
  const auto separates = [error](double projection, double radius_a, double radius_b) {
    return std::fabs(projection) - (radius_a + radius_b) > error;
  };

  for (int i = 0; i < 3; ++i) {  // a's face normals
    for (int j = 0; j < 3; ++j) {
      r[i][j] = dot(a.axes.col[i], b.axes.col[j]);
      abs_r[i][j] = std::fabs(r[i][j]);
    }
    ta[i] = dot(a.axes.col[i], d);
    const double rb = fp::sum3(b.half.x * abs_r[i][0], b.half.y * abs_r[i][1], b.half.z * abs_r[i][2]);
    records.add(bounds::ObbAxis{i, 0, ta[i], 0, a.half[i], rb});
    if (separates(ta[i], a.half[i], rb)) return false;
  }
  const Vec3 tb = transpose_times(b.axes, d);  // d in b's frame
  for (int j = 0; j < 3; ++j) {  // b's face normals
    const double ra = fp::sum3(a.half.x * abs_r[0][j], a.half.y * abs_r[1][j], a.half.z * abs_r[2][j]);
    records.add(bounds::ObbAxis{3 + j, 0, tb[j], 0, ra, b.half[j]});
    if (separates(tb[j], ra, b.half[j])) return false;
  }
  for (int i = 0; i < 3; ++i) {  // a_i x b_j
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      // d . (a_i x b_j) in a's frame and in b's frame. Each is exact up to a sign (a frame may be
      // a mirror image, det = -1) and rounding; the axis separates only if it does in both.
      const double in_a = ta[i2] * r[i1][j] - ta[i1] * r[i2][j];
      const double in_b = r[i][j2] * tb[j1] - r[i][j1] * tb[j2];
      const double ra = a.half[i1] * abs_r[i2][j] + a.half[i2] * abs_r[i1][j];
      const double rb = b.half[j1] * abs_r[i][j2] + b.half[j2] * abs_r[i][j1];
      records.add(bounds::ObbAxis{6 + 3 * i + j, 0, in_a, 0, ra, rb});
      records.add(bounds::ObbAxis{6 + 3 * i + j, 1, in_b, 0, ra, rb});
      if (separates(std::min(std::fabs(in_a), std::fabs(in_b)), ra, rb)) return false;
    }
  }
  // On the hit path only: inputs outside the contract give false.
  return finite(a.center) && finite(b.center) && finite(a.half) && finite(b.half) && finite(a.axes) &&
         finite(b.axes) && a.half.x >= 0 && a.half.y >= 0 && a.half.z >= 0 && b.half.x >= 0 && b.half.y >= 0 &&
         b.half.z >= 0;
}

}  // namespace

bool test_obb_obb(const Obb& a, const Obb& b) {
  bounds::NoRecords none;
  return test(a, b, none);
}

bool test_obb_obb(const Obb& a, const Obb& b, bounds::Records& records) { return test(a, b, records); }

}  // namespace cc
