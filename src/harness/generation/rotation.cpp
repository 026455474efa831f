#include "harness/generation/rotation.h"

#include <cmath>
#include <utility>
#include <vector>

namespace cc::harness {
namespace {

// A rotation about coordinate axis `axis` with cosine c and sine s.
Mat3 about_axis(int axis, double c, double s) {
  Mat3 m;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m(i, i) = c;
  m(i, j) = -s;
  m(j, i) = s;
  m(j, j) = c;
  return m;
}

double unit_interval(Choices& c) { return static_cast<double>(c.draw(std::uint64_t{1} << 53)) * 0x1p-53; }

}  // namespace

Mat3 from_quaternion(double w, double x, double y, double z) {
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  Mat3 m;
  m(0, 0) = 1 - 2 * (y * y + z * z);
  m(0, 1) = 2 * (x * y - w * z);
  m(0, 2) = 2 * (x * z + w * y);
  m(1, 0) = 2 * (x * y + w * z);
  m(1, 1) = 1 - 2 * (x * x + z * z);
  m(1, 2) = 2 * (y * z - w * x);
  m(2, 0) = 2 * (x * z - w * y);
  m(2, 1) = 2 * (y * z + w * x);
  m(2, 2) = 1 - 2 * (x * x + y * y);
  return m;
}

namespace {

std::vector<Mat3> rotation_table() {
  std::vector<Mat3> table;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms) {
    for (int signs = 0; signs < 8; ++signs) {
      Mat3 m;
      for (int j = 0; j < 3; ++j) {
        m.col[j] = Vec3{};
        m.col[j][p[j]] = (signs >> j) & 1 ? -1.0 : 1.0;
      }
      if (dot(cross(m.col[0], m.col[1]), m.col[2]) > 0) table.push_back(m);
    }
  }
  const double q[8][4] = {{0.9, 0.1, -0.3, 0.2},   {0.2, 0.7, 0.1, -0.6},  {-0.5, 0.5, 0.5, 0.5}, {0.3, -0.2, 0.9, 0.1},
                          {0.6, 0.6, -0.2, -0.4},  {0.1, 0.05, 0.02, 0.99}, {0.7, -0.1, 0.1, 0.7}, {0.4, 0.8, 0.4, 0.2}};
  for (const auto& r : q) table.push_back(from_quaternion(r[0], r[1], r[2], r[3]));
  return table;
}

}  // namespace

const Mat3& table_rotation(std::size_t index) {
  static const std::vector<Mat3> table = rotation_table();
  return table[index % table.size()];
}

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 m;
  for (int j = 0; j < 3; ++j) m.col[j] = a * b.col[j];
  return m;
}

Mat3 draw_rotation(ValueSource& values) {
  Choices& c = values.choices();
  switch (c.draw(6)) {
    case 0: return Mat3::identity();
    case 1: {  // signed permutation
      int p[3] = {0, 1, 2};
      for (int i = 2; i > 0; --i) std::swap(p[i], p[c.draw(static_cast<std::uint64_t>(i) + 1)]);
      Mat3 m;
      for (int j = 0; j < 3; ++j) {
        m.col[j] = Vec3{};
        m.col[j][p[j]] = c.chance(50) ? -1.0 : 1.0;
      }
      return m;
    }
    case 2: {  // dyadic small rotation: c = 1 - 2^-(2k+1), s = 2^-k, so c^2 + s^2 = 1 + 2^-(4k+2)
      const int k = 13 + static_cast<int>(c.draw(18));
      const double s = std::ldexp(c.chance(50) ? -1.0 : 1.0, -k);
      return about_axis(static_cast<int>(c.draw(3)), 1 - std::ldexp(1.0, -(2 * k + 1)), s);
    }
    case 3: {  // generic angle about a coordinate axis
      const double angle = 2 * M_PI * unit_interval(c);
      return about_axis(static_cast<int>(c.draw(3)), std::cos(angle), std::sin(angle));
    }
    default: {  // from a quaternion, each component 0 a quarter of the time (all four: none)
      const auto q = [&c] { return c.chance(25) ? 0.0 : 2 * unit_interval(c) - 1; };
      double w = q(), x = q(), y = q(), z = q();
      if (w == 0 && x == 0 && y == 0 && z == 0) w = 1;
      return from_quaternion(w, x, y, z);
    }
  }
}

Mat3 draw_rotation_near(ValueSource& values, const Mat3& base) {
  Choices& c = values.choices();
  switch (c.draw(3)) {
    case 0: return base;
    case 1: {
      Mat3 m = base;
      const int i = static_cast<int>(c.draw(3)), j = static_cast<int>(c.draw(3));
      m(i, j) = values.nudge(m(i, j));
      return m;
    }
    default: {
      const double angle = std::ldexp(1.0 + unit_interval(c), -20 - static_cast<int>(c.draw(30)));
      return multiply(base, about_axis(static_cast<int>(c.draw(3)), std::cos(angle), std::sin(angle)));
    }
  }
}

Mat3 draw_non_orthonormal(ValueSource& values) {
  Choices& c = values.choices();
  Mat3 m = draw_rotation(values);
  const int j = static_cast<int>(c.draw(3));
  if (c.chance(50)) {
    m.col[j] = (1 + std::ldexp(1.0, -10 - static_cast<int>(c.draw(30)))) * m.col[j];  // scaled column
  } else {
    m.col[j] = m.col[j] + std::ldexp(1.0, -5 - static_cast<int>(c.draw(30))) * m.col[(j + 1) % 3];  // shear
  }
  return m;
}

}  // namespace cc::harness
