// Generators for tri_aabb, tri_obb and tri_tri: a vertex exactly on a corner, edge or face of
// the box; triangles in the plane of a face; shared vertices; a vertex on the other triangle's
// edge; coplanar triangles; degenerate triangles (segments, points); point and segment boxes in
// a triangle's plane; and ULP-sized offsets.
#include <cmath>
#include <utility>

#include "harness/generate_detail.h"
#include "harness/rotation.h"

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

}  // namespace

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
  return t;
}

TriAabbInput generate_tri_aabb(ValueSource& v, const GenerateOptions& options) {
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

TriTriInput generate_tri_tri(ValueSource& v, const GenerateOptions&) {
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
