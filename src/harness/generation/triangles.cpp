// Triangles for the generators: a vertex exactly on a corner, edge or face of a box; triangles in
// the plane of a face; degenerate triangles (segments, points); triangles through point and
// segment boxes in their plane; triangles in the regimes of the triangle tests' bounds.
#include "harness/generation/triangles.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "harness/generation/rotation.h"

namespace cc::harness {
namespace {

// A point apart from p, away from the box's centre on every axis: with one such vertex on the
// box's boundary and the others outward, the triangle touches the box at that vertex only.
Vec3 outward_from(ValueSource& v, const Aabb& box, const Vec3& p) {
  Vec3 q = p;
  for (int k = 0; k < 3; ++k) {
    const double magnitude = std::fabs(v.coordinate());
    const double step = magnitude + (v.choices().chance(50) ? 0.0 : 1.0);
    const bool up = p[k] >= 0.5 * (box.lo[k] + box.hi[k]);
    q[k] = up ? p[k] + step : p[k] - step;
  }
  return q;
}

// A generic double in [lo, hi).
double between(Choices& c, double lo, double hi) { return lo + (hi - lo) * static_cast<double>(c.draw(std::uint64_t{1} << 52)) * 0x1p-52; }

}  // namespace

Triangle triangle_touching_at_a_vertex(ValueSource& v, const Aabb& box) {
  Triangle t;
  t.v[0] = draw_boundary_point(v, box);
  t.v[1] = outward_from(v, box, t.v[0]);
  t.v[2] = v.choices().chance(30) ? t.v[1] : outward_from(v, box, t.v[0]);
  if (v.choices().chance(30)) {  // a few ULPs off the boundary on one axis
    const int k = static_cast<int>(v.choices().draw(3));
    t.v[0][k] = v.nudge(t.v[0][k]);
  }
  shuffle_vertices(v.choices(), t);
  return t;
}

// A triangle against the box [box.lo, box.hi] (in the box's own frame).
Triangle triangle_near_box(ValueSource& v, const Aabb& box) {
  Triangle t;
  switch (v.choices().draw(5)) {
    case 0: return draw_triangle(v);
    case 1: return triangle_touching_at_a_vertex(v, box);  // at a corner, an edge, a face, or just off it
    case 2: {  // in the plane of a face (or a few ULPs off it)
      const int k = static_cast<int>(v.choices().draw(3));
      const double plane = v.choices().chance(50) ? box.lo[k] : box.hi[k];
      for (Vec3& p : t.v) {
        p = v.choices().chance(50) ? draw_boundary_point(v, box) : v.point();
        p[k] = plane;
      }
      if (v.choices().chance(30)) t.v[0][k] = v.nudge(plane);
      return t;
    }
    case 3: {  // inside, or spanning the box
      for (Vec3& p : t.v) p = v.choices().chance(50) ? 0.5 * (box.lo + box.hi) + v.point() : draw_boundary_point(v, box);
      return t;
    }
    default: {  // an edge through two boundary points
      t.v[0] = draw_boundary_point(v, box);
      t.v[1] = draw_boundary_point(v, box);
      t.v[2] = v.point();
      return t;
    }
  }
}

// The box collapsed to a point (its lo corner) or to a segment along axis k: zero extent on
// every axis but k. (In an Obb's frame: the half extents set to 0 likewise.)
int collapse(ValueSource& v, Aabb& box) {
  const int k = v.choices().chance(50) ? static_cast<int>(v.choices().draw(3)) : -1;
  for (int j = 0; j < 3; ++j) {
    if (j != k) box.hi[j] = box.lo[j];
  }
  return k;
}

// A triangle in a tilted plane through a point or segment box (axis k, or -1 for a point):
// vertices box.lo + a u + b w for small integers a, b, with u along the segment. The box lies
// inside the triangle, on its boundary or outside it, in its plane (up to the rounding of the
// vertices), where the Minkowski difference is flat and the 13 usual axes cannot separate.
Triangle triangle_through_flat_box(ValueSource& v, const Aabb& box, int k) {
  const auto small = [&v] { return static_cast<double>(v.small_int(3)); };
  Vec3 u{small(), small(), small()}, w{small(), small(), small()};
  if (k >= 0) u = Vec3{}, u[k] = 1;
  Triangle t;
  for (Vec3& p : t.v) p = box.lo + small() * u + small() * w;
  return t;
}

Vec3 centroid(const Triangle& t) { return (1.0 / 3) * (t.v[0] + t.v[1] + t.v[2]); }

// The largest |(v - centroid) . w| over the vertices.
double triangle_reach_along(const Triangle& t, const Vec3& w) {
  const Vec3 c = centroid(t);
  return std::max({std::fabs(dot(t.v[0] - c, w)), std::fabs(dot(t.v[1] - c, w)), std::fabs(dot(t.v[2] - c, w))});
}

// A frame for a triangle against a box with the given axes: the box's own (a face's plane, an
// edge's direction), nearly those, or any.
Mat3 frame_against(ValueSource& v, const Mat3& axes) {
  switch (v.choices().draw(3)) {
    case 0: return multiply(axes, table_rotation(v.choices().draw(24)));
    case 1: return nearly_parallel(v, multiply(axes, table_rotation(v.choices().draw(24))));
    default: return draw_rotation(v);
  }
}

// The direction to slide along: one of the axes given, or any.
Vec3 along_an_axis_or_any(ValueSource& v, const Mat3& axes) {
  const Vec3 w = v.choices().chance(70) ? axes.col[v.choices().draw(3)] : draw_direction(v);
  return v.choices().chance(50) ? -1.0 * w : w;
}

Triangle triangle_in_regime(ValueSource& v, double size, const Mat3& frame) {
  Choices& c = v.choices();
  const auto tilt = [&c] {
    switch (c.draw(3)) {
      case 0: return 0.0;
      case 1: {
        const double sign = c.chance(50) ? -1.0 : 1.0;
        const int shift = 8 + static_cast<int>(c.draw(45));
        return sign * std::ldexp(between(c, 1, 2), -shift);
      }
      default: return between(c, -1, 1);
    }
  };
  double thin = 0;
  if (c.chance(40)) {
    thin = between(c, 0.25, 1);
  } else {
    const int shift = static_cast<int>(c.draw(41));
    thin = std::ldexp(between(c, 1, 2), -shift);
  }
  const Vec3 q[3] = {{0, 0, 0}, {1, 0, tilt()}, {between(c, -0.5, 1.5), thin, tilt()}};
  Triangle t;
  for (int k = 0; k < 3; ++k) t.v[k] = frame * (size * q[k]);
  shuffle_vertices(c, t);
  return t;
}

void shuffle_vertices(Choices& c, Triangle& t) {
  for (std::size_t i = 3; i > 1; --i) std::swap(t.v[i - 1], t.v[c.draw(i)]);
}

Triangle translated(const Triangle& t, const Vec3& by) { return {{t.v[0] + by, t.v[1] + by, t.v[2] + by}}; }

Triangle draw_triangle(ValueSource& v) {
  Triangle t;
  for (Vec3& p : t.v) p = v.point();
  switch (v.choices().draw(6)) {
    case 0: t.v[2] = t.v[0] + 2.0 * (t.v[1] - t.v[0]); break;  // collinear: a segment
    case 1: t.v[2] = 0.5 * (t.v[0] + t.v[1]); break;            // collinear, the middle vertex last
    case 2: t.v[1] = t.v[2] = t.v[0]; break;                    // a point
    case 3: t.v[1] = t.v[0]; break;                             // two equal vertices
    default: break;
  }
  shuffle_vertices(v.choices(), t);
  return t;
}

}  // namespace cc::harness
