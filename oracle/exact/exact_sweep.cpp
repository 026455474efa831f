#include "oracle/exact/exact_sweep.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>

#include "oracle/exact/dyadic.h"

namespace cc::exact {

void ExactWindow::restrict(const Rational& p, const Rational& s, const Rational& r) {
  if (sgn(s) == 0) {
    if (abs(p) > r) first = 1, last = 0;
    return;
  }
  Rational enter = (-r - p) / s, exit = (r - p) / s;
  if (sgn(s) < 0) std::swap(enter, exit);
  first = std::max(first, enter);
  last = std::min(last, exit);
}

namespace {

// moving_axes for boxes whose edge directions span space, on integers (dyadic.h): the columns
// of both boxes on one power of two 2^C, their centres on 2^P, their velocities on 2^V and their
// half extents on 2^H (each the lowest last bit of its kind, so that a tiny velocity does not
// lengthen the columns' integers). Cross products are then on 2^2C, p on 2^(2C + P), s on
// 2^(2C + V) and r on 2^(3C + H): the same axes, names, conditionings and rationals as the
// rational path, without a gcd on the way. Nothing for directions that do not span space.
std::optional<std::vector<MovingAxis>> spanning_moving_axes(const MovingObb& a, const MovingObb& b) {
  const auto lowest_of = [&a, &b](auto member) {
    long lowest = 0;
    for (const MovingObb* m : {&a, &b}) {
      for (const Vec3* v : member(*m)) lowest = lowest_exponent(*v, lowest);
    }
    return lowest;
  };
  const long columns = lowest_of([](const MovingObb& m) {
    return std::array<const Vec3*, 3>{&m.box.axes.col[0], &m.box.axes.col[1], &m.box.axes.col[2]};
  });
  const long centres = lowest_of([](const MovingObb& m) { return std::array<const Vec3*, 1>{&m.box.center}; });
  const long velocities = lowest_of([](const MovingObb& m) { return std::array<const Vec3*, 1>{&m.velocity}; });
  const long halves = lowest_of([](const MovingObb& m) { return std::array<const Vec3*, 1>{&m.box.half}; });
  // The directions of parallelepiped_shape: the columns with a nonzero half extent and length.
  static const char* kAxisNames[] = {"x", "y", "z"};
  std::vector<IntVec3> dirs, half_edges;
  std::vector<std::string> names;
  for (const MovingObb* m : {&a, &b}) {
    for (int i = 0; i < 3; ++i) {
      const Vec3& column = m->box.axes.col[i];
      if (m->box.half[i] == 0 || (column.x == 0 && column.y == 0 && column.z == 0)) continue;
      dirs.push_back(on_grid(column, columns));
      mpz_class half;
      set_on(half, m->box.half[i], halves);
      IntVec3 h;
      for (int k = 0; k < 3; ++k) mpz_mul(h[k].get_mpz_t(), half.get_mpz_t(), dirs.back()[k].get_mpz_t());
      half_edges.push_back(std::move(h));
      names.push_back(std::string(m == &a ? "A" : "B") + "." + kAxisNames[i]);
    }
  }
  const std::size_t n = dirs.size();
  std::vector<IntVec3> crosses(n * n);
  bool spans = false;
  mpz_class t;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      cross(crosses[i * n + j], dirs[i], dirs[j]);
      for (std::size_t k = 0; k < n && !spans; ++k) {
        dot(t, crosses[i * n + j], dirs[k]);
        spans = sgn(t) != 0;
      }
    }
  }
  if (!spans) return std::nullopt;
  std::vector<Magnitude> lengths;
  for (const IntVec3& d : dirs) {
    dot(t, d, d);
    lengths.push_back(length_from_square(t, columns));
  }
  IntVec3 d = on_grid(b.box.center, centres), w = on_grid(b.velocity, velocities);
  const IntVec3 ca = on_grid(a.box.center, centres), va = on_grid(a.velocity, velocities);
  for (int k = 0; k < 3; ++k) d[k] -= ca[k], w[k] -= va[k];
  std::vector<MovingAxis> out;
  mpz_class p, s, r;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const IntVec3& c = crosses[i * n + j];
      if (is_zero(c)) continue;
      r = 0;
      for (const IntVec3& h : half_edges) {
        dot(t, c, h);
        mpz_abs(t.get_mpz_t(), t.get_mpz_t());
        r += t;
      }
      dot(p, c, d);
      dot(s, c, w);
      const QVec3 axis{rational_on(c[0], 2 * columns), rational_on(c[1], 2 * columns), rational_on(c[2], 2 * columns)};
      out.push_back({{names[i] + " x " + names[j], axis, lengths[i] * lengths[j]},
                     rational_on(p, 2 * columns + centres),
                     rational_on(s, 2 * columns + velocities),
                     rational_on(r, 3 * columns + halves)});
    }
  }
  return out;
}

}  // namespace

std::vector<MovingAxis> moving_axes(const MovingObb& a, const MovingObb& b) {
  if (std::optional<std::vector<MovingAxis>> axes = spanning_moving_axes(a, b)) return std::move(*axes);
  const ExactShape sa = parallelepiped_shape(a.box.center, a.box.half, a.box.axes, "A");
  const ExactShape sb = parallelepiped_shape(b.box.center, b.box.half, b.box.axes, "B");
  const QVec3 d = sb.center - sa.center;
  const QVec3 w = rational(b.velocity) - rational(a.velocity);
  std::vector<MovingAxis> out;
  for (CandidateAxis& c : candidate_axes_for_any_offset(sa, sb)) {
    Rational r = 0;
    for (const QVec3& h : sa.half_edges) r += abs(dot(c.axis, h));
    for (const QVec3& h : sb.half_edges) r += abs(dot(c.axis, h));
    const Rational p = dot(c.axis, d), s = dot(c.axis, w);
    out.push_back({std::move(c), p, s, r});
  }
  return out;
}

ExactWindow exact_sweep(const std::vector<MovingAxis>& axes, const Rational& grow) {
  ExactWindow window;
  for (const MovingAxis& m : axes) {
    if (sgn(grow) == 0) {
      window.restrict(m.p, m.s, m.r);
    } else {
      window.restrict(m.p, m.s, m.r + grow * rational(m.axis.conditioning.to_double()));
    }
    if (!window.hit()) break;
  }
  return window;
}

ExactWindow exact_sweep(const Aabb& a, const Vec3& va, const Aabb& b, const Vec3& vb) {
  ExactWindow window;
  for (int k = 0; k < 3; ++k) {
    // a.lo - b.hi <= t w <= a.hi - b.lo, as |p + t s| <= r with the centre and half width.
    const Rational low = rational(a.lo[k]) - rational(b.hi[k]);
    const Rational high = rational(a.hi[k]) - rational(b.lo[k]);
    const Rational w = rational(vb[k]) - rational(va[k]);
    window.restrict(-(low + high) / 2, w, (high - low) / 2);
  }
  return window;
}

}  // namespace cc::exact
