// Generators for tri_aabb, tri_obb and tri_tri: a vertex exactly on a corner, edge or face of
// the box; triangles in the plane of a face; shared vertices; a vertex on the other triangle's
// edge; coplanar triangles; degenerate triangles (segments, points); point and segment boxes in
// a triangle's plane; and ULP-sized offsets.
#include <algorithm>
#include <cmath>
#include <utility>

#include "harness/generation/shapes.h"
#include "harness/generation/rotation.h"

namespace cc::harness::detail {
namespace {

// A point apart from p, away from the box's centre on every axis: with one such vertex on the
// box's boundary and the others outward, the triangle touches the box at that vertex only.
Vec3 outward_from(ValueSource& v, const Aabb& box, const Vec3& p) {
  Vec3 q = p;
  for (int k = 0; k < 3; ++k) {
    const double step = std::fabs(v.coordinate()) + (v.choices().chance(50) ? 0.0 : 1.0);
    const bool up = p[k] >= 0.5 * (box.lo[k] + box.hi[k]);
    q[k] = up ? p[k] + step : p[k] - step;
  }
  return q;
}

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

namespace {

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

// A generic double in [lo, hi).
double between(Choices& c, double lo, double hi) { return lo + (hi - lo) * static_cast<double>(c.draw(std::uint64_t{1} << 52)) * 0x1p-52; }

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

// `t` slid from `center` along w to the target margin: the family of a bound-reaching case.
template <class In, class Put>
In slid_to_the_bound(ValueSource& v, const GenerateOptions& options, const Triangle& t, const Vec3& center,
                     double other_reach, const Vec3& w, Put put) {
  const Triangle start = translated(t, center - centroid(t));
  const auto placed = [&](double s) { return put(translated(start, s * w)); };
  const double contact = (other_reach + triangle_reach_along(t, w)) / dot(w, w);
  const double apart = 2 * contact + 1 / std::sqrt(dot(w, w));
  const double s = place_at([&placed](double x) -> Input { return placed(x); }, 0, apart,
                            draw_margin_target(v.choices()), options, contact);
  return placed(s);
}

// The direction to slide along: one of the axes given, or any.
Vec3 along_an_axis_or_any(ValueSource& v, const Mat3& axes) {
  const Vec3 w = v.choices().chance(70) ? axes.col[v.choices().draw(3)] : draw_direction(v);
  return v.choices().chance(50) ? -1.0 * w : w;
}

// A triangle and a box at an exact margin in the regimes of test_triangle_aabb's bound: boxes of
// aspect ratio up to 2^40 far from the origin, slivers nearly coplanar with a face or nearly
// parallel to an edge.
TriAabbInput tri_aabb_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const double size = draw_size(v);
  const Vec3 center = v.point() + draw_far_offset(v, size), half = draw_aspect_extents(v, size);
  const Aabb box{center - half, center + half};
  const Triangle t = triangle_in_regime(v, std::ldexp(size, v.small_int(20)), frame_against(v, Mat3::identity()));
  const Vec3 w = along_an_axis_or_any(v, Mat3::identity());
  const double box_reach = std::fabs(half.x * w.x) + std::fabs(half.y * w.y) + std::fabs(half.z * w.z);
  return slid_to_the_bound<TriAabbInput>(v, options, t, 0.5 * (box.lo + box.hi), box_reach, w,
                                         [&box](const Triangle& moved) { return TriAabbInput{moved, box}; });
}

// The same for test_triangle_obb: the box's axes also at the orthonormality tolerance.
TriObbInput tri_obb_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const double size = draw_size(v);
  Obb box{v.point() + draw_far_offset(v, size), draw_aspect_extents(v, size), draw_rotation(v)};
  if (v.choices().chance(60)) box.axes = perturb_to_tolerance(v, box.axes);
  const Triangle t = triangle_in_regime(v, std::ldexp(size, v.small_int(20)), frame_against(v, box.axes));
  const Vec3 w = along_an_axis_or_any(v, box.axes);
  return slid_to_the_bound<TriObbInput>(v, options, t, box.center, reach_along(box, w), w,
                                        [&box](const Triangle& moved) { return TriObbInput{moved, box}; });
}

// Two triangles at an exact margin in the regimes of test_triangle_triangle's bound: slivers far
// from the origin, coplanar or nearly, with edges parallel or nearly, of sizes up to 2^20 apart.
TriTriInput tri_tri_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const double size = draw_size(v);
  const Mat3 frame = draw_rotation(v);
  const Triangle a = translated(triangle_in_regime(v, size, frame), v.point() + draw_far_offset(v, size));
  const Mat3 other = v.choices().chance(30) ? frame : (v.choices().chance(60) ? nearly_parallel(v, frame) : draw_rotation(v));
  const Triangle b = triangle_in_regime(v, std::ldexp(size, v.small_int(20)), other);
  const Vec3 w = along_an_axis_or_any(v, frame);
  TriTriInput in = slid_to_the_bound<TriTriInput>(v, options, b, centroid(a), triangle_reach_along(a, w), w,
                                                  [&a](const Triangle& moved) { return TriTriInput{a, moved}; });
  if (v.choices().chance(50)) std::swap(in.a, in.b);
  return in;
}

}  // namespace

Triangle triangle_in_regime(ValueSource& v, double size, const Mat3& frame) {
  Choices& c = v.choices();
  const auto tilt = [&c] {
    switch (c.draw(3)) {
      case 0: return 0.0;
      case 1: return (c.chance(50) ? -1.0 : 1.0) * std::ldexp(between(c, 1, 2), -static_cast<int>(8 + c.draw(45)));
      default: return between(c, -1, 1);
    }
  };
  const double thin = c.chance(40) ? between(c, 0.25, 1) : std::ldexp(between(c, 1, 2), -static_cast<int>(c.draw(41)));
  const Vec3 q[3] = {{0, 0, 0}, {1, 0, tilt()}, {between(c, -0.5, 1.5), thin, tilt()}};
  Triangle t;
  for (int k = 0; k < 3; ++k) t.v[k] = frame * (size * q[k]);
  shuffle_vertices(c, t);
  return t;
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

TriAabbInput generate_tri_aabb(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return tri_aabb_at_the_bound(v, options);
  TriAabbInput in;
  in.box = draw_aabb(v, options);
  if (v.choices().chance(15)) {  // a flat configuration: a point or segment box in the triangle's plane
    const int k = collapse(v, in.box);
    in.tri = triangle_through_flat_box(v, in.box, k);
    return in;
  }
  in.tri = triangle_near_box(v, in.box);
  return in;
}

TriObbInput generate_tri_obb(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return tri_obb_at_the_bound(v, options);
  TriObbInput in;
  in.box = draw_obb(v, options);
  // Built in the box's frame, then taken to the world: exact for exactly orthonormal axes and
  // simple values, otherwise within a few ULPs of the constructed contact.
  Triangle local;
  if (v.choices().chance(15)) {  // a flat configuration, as for tri_aabb
    Aabb flat{-in.box.half, in.box.half};
    const int k = collapse(v, flat);
    for (int j = 0; j < 3; ++j) {
      if (j != k) in.box.half[j] = 0;
    }
    flat = Aabb{-in.box.half, in.box.half};
    local = triangle_through_flat_box(v, flat, k);
  } else {
    local = triangle_near_box(v, Aabb{-in.box.half, in.box.half});
  }
  for (int i = 0; i < 3; ++i) in.tri.v[i] = in.box.center + in.box.axes * local.v[i];
  return in;
}

TriTriInput generate_tri_tri(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return tri_tri_at_the_bound(v, options);
  TriTriInput in;
  in.a = draw_triangle(v);
  in.b = draw_triangle(v);
  switch (v.choices().draw(6)) {
    case 0: break;
    case 1: in.b.v[0] = in.a.v[v.choices().draw(3)]; break;  // a shared vertex
    case 2: {                                                 // a vertex on an edge
      const int i = static_cast<int>(v.choices().draw(3));
      const double t = static_cast<double>(1 + v.choices().draw(3)) / 4;
      in.b.v[0] = in.a.v[i] + t * (in.a.v[(i + 1) % 3] - in.a.v[i]);
      break;
    }
    case 3: {  // coplanar: one coordinate equal for all six vertices (or one a few ULPs off)
      const int k = static_cast<int>(v.choices().draw(3));
      const double plane = in.a.v[0][k];
      for (Triangle* t : {&in.a, &in.b}) {
        for (Vec3& p : t->v) p[k] = plane;
      }
      if (v.choices().chance(30)) in.b.v[0][k] = v.nudge(plane);
      break;
    }
    case 4: {  // B is A moved by a few ULPs along one axis (or not at all)
      in.b = in.a;
      const int k = static_cast<int>(v.choices().draw(3));
      for (Vec3& p : in.b.v) p[k] = v.nudge(p[k]);
      break;
    }
    default: {  // an edge of B crossing an edge of A at its middle, in a common plane
      const int i = static_cast<int>(v.choices().draw(3));
      const Vec3 mid = 0.5 * (in.a.v[i] + in.a.v[(i + 1) % 3]);
      const Vec3 d = v.point();
      in.b.v[0] = mid + d;
      in.b.v[1] = mid - d;
    }
  }
  if (v.choices().chance(50)) std::swap(in.a, in.b);
  return in;
}

}  // namespace cc::harness::detail
