// What to draw of a case, derived from its fields (fields.h): segments, circles and points in
// space, each of shape 0 or 1 (the first part that draws and the second, e.g. A and B), and
// rays, which the renderer draws as far as the rest reaches. `crosscheck triage --svg` renders
// it in three orthographic views.
#pragma once

#include <vector>

#include "collide/ray.h"
#include "harness/model/input.h"

namespace cc::harness {

struct Drawing {
  struct Segment {
    Vec3 p, q;
    int shape;
  };
  struct Circle {
    Vec3 center;
    double radius;
    int shape;
  };
  struct Point {
    Vec3 p;
    int shape;
  };
  struct RayLine {
    Ray ray;
    int shape;
  };
  std::vector<Segment> segments;
  std::vector<Circle> circles;
  std::vector<Point> points;
  std::vector<RayLine> rays;
};

/// The parts of a case: a box (axis-aligned or oriented) by its edges, a sphere by its outline
/// (a circle in each view), a triangle by its edges and vertices (a degenerate one stays
/// visible), a point set by its points, a ray from its origin, a moving box at the start and the
/// end of its step, a mesh by its first 400 faces, two placed meshes by their first 200 faces
/// each, boxes over frames by the last frame's boxes, a disc by its outline and walls by their
/// segments and ends, in the plane z = 0 (the walls one shape).
Drawing drawing_of(const Input& input);

/// The rays as segments: each clipped to [tmin, tmax] and to twice the distance (in the largest
/// coordinate, at least 1) from its origin to the farthest point drawn, with its origin as a
/// point; appended after the rest.
void draw_rays(Drawing& drawing);

}  // namespace cc::harness
