#include "harness/generation/touch.h"

#include <cmath>

namespace cc::harness {

void put_vertex_at(Triangle& t, int i, const Vec3& p) {
  const Vec3 by = p - t.v[static_cast<std::size_t>(i)];
  for (Vec3& v : t.v) v = v + by;
  t.v[static_cast<std::size_t>(i)] = p;
}

void place_against_face(const Obb& a, Obb& b, ValueSource& v, bool nudged) {
  const int k = static_cast<int>(v.choices().draw(3));
  const Vec3 n = a.axes.col[k];
  double rb = 0;
  for (int j = 0; j < 3; ++j) rb += b.half[j] * std::fabs(dot(n, b.axes.col[j]));
  double reach = a.half[k] + rb;
  if (nudged) reach = v.nudge(reach);
  const double sign = v.choices().chance(50) ? -1.0 : 1.0;
  Vec3 c = a.center + (sign * reach) * n;
  for (int i = 1; i < 3; ++i) {
    const int j = (k + i) % 3;
    const double along = v.choices().chance(50) ? 0.0 : a.half[j] * (v.choices().chance(50) ? 1.0 : 0.5);
    c = c + (v.choices().chance(50) ? along : -along) * a.axes.col[j];
  }
  b.center = c;
}

void put_face_to_face(const Aabb& a, Aabb& b, Choices& c) {
  const int k = static_cast<int>(c.draw(3));
  const double extent = b.hi[k] - b.lo[k];
  if (c.chance(50)) {
    b.lo[k] = a.hi[k], b.hi[k] = a.hi[k] + extent;
  } else {
    b.hi[k] = a.lo[k], b.lo[k] = a.lo[k] - extent;
  }
}

void touch_at_vertices(MeshPair& m, Choices& c) {
  const Mesh &a = *m.a.mesh, &b = *m.b.mesh;
  if (a.vertices.empty() || b.vertices.empty()) return;
  const Vec3 on_a = apply(m.pose_a, a.vertices[c.draw(a.vertices.size())]);
  const Vec3 on_b = apply(m.pose_b, b.vertices[c.draw(b.vertices.size())]);
  m.pose_b.translation = m.pose_b.translation + (on_a - on_b);
}

void make_touching(Input& input, ValueSource& v) {
  std::visit([&v]<class In>(In& in) { Query<In>::touch(in, v); }, input);
}

}  // namespace cc::harness
