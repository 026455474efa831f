#include "harness/generation/touch.h"
#include "harness/model/kind_pieces.h"

#include <cmath>

namespace cc::harness {

void put_vertex_at(Triangle& t, int i, const Vec3& p) {
  const Vec3 by = p - t.v[static_cast<std::size_t>(i)];
  for (Vec3& v : t.v) v = v + by;
  t.v[static_cast<std::size_t>(i)] = p;
}

void place_against_face(const Obb& a, Obb& b, ValueSource& v, bool nudged) {
  Choices& c = v.choices();
  const int k = static_cast<int>(c.draw(3));
  const Vec3 n = (c.chance(50) ? -1.0 : 1.0) * a.axes.col[k];  // the face's outward normal
  // A point of the face: its centre, or a point halfway to or on an edge, or a corner.
  Vec3 target = a.center + a.half[k] * n;
  for (int i = 1; i < 3; ++i) {
    const int j = (k + i) % 3;
    const double along = c.chance(50) ? 0.0 : a.half[j] * (c.chance(50) ? 1.0 : 0.5);
    target = target + (c.chance(50) ? along : -along) * a.axes.col[j];
  }
  // B's corner farthest against the normal (on a tie, either) lands on it: B lies beyond the
  // face's plane and touches the face there.
  Vec3 corner;
  double reach = 0;
  for (int j = 0; j < 3; ++j) {
    const double d = dot(n, b.axes.col[j]);
    const double side = d > 0 ? -1.0 : d < 0 ? 1.0 : (c.chance(50) ? -1.0 : 1.0);
    corner = corner + (side * b.half[j]) * b.axes.col[j];
    reach += b.half[j] * std::fabs(d);
  }
  b.center = target - corner;
  if (nudged) {  // a few ULPs of B's reach beyond the face or into A
    reach += a.half[k];
    b.center = b.center + (v.nudge(reach) - reach) * n;
  }
}

void put_face_to_face(const Aabb& a, Aabb& b, Choices& c) {
  const int k = static_cast<int>(c.draw(3));
  const double extent = b.hi[k] - b.lo[k];
  if (c.chance(50)) {
    b.lo[k] = a.hi[k], b.hi[k] = a.hi[k] + extent;
  } else {
    b.hi[k] = a.lo[k], b.lo[k] = a.lo[k] - extent;
  }
  // On the other axes, B moved onto A's range where it misses it: its near side on A's far one.
  for (int i = 1; i < 3; ++i) {
    const int j = (k + i) % 3;
    const double other = b.hi[j] - b.lo[j];
    if (b.lo[j] > a.hi[j]) b.lo[j] = a.hi[j], b.hi[j] = a.hi[j] + other;
    if (b.hi[j] < a.lo[j]) b.hi[j] = a.lo[j], b.lo[j] = a.lo[j] - other;
  }
}

void touch_at_vertices(MeshPair& m, Choices& c) {
  const Mesh &a = *m.a.mesh, &b = *m.b.mesh;
  if (a.vertices.empty() || b.vertices.empty()) return;
  const Vec3 on_a = apply(m.pose_a, a.vertices[c.draw(a.vertices.size())]);
  // The new translation from b's vertex turned alone, so that b's old translation (however far)
  // adds no rounding of its own.
  const Vec3 turned = m.pose_b.rotation * b.vertices[c.draw(b.vertices.size())];
  m.pose_b.translation = on_a - turned;
}

void make_touching(Input& input, ValueSource& v) {
  pieces_of(kind_of(input)).touch(input, v);
}

}  // namespace cc::harness
