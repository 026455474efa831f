#include "harness/generation/touch.h"

#include <cmath>

#include "collide/kdop.h"
#include "harness/generation/shapes.h"

namespace cc::harness {
namespace {

Vec3 translated(const Vec3& p, const Vec3& by) { return p + by; }

// Moves a triangle so that its vertex i lands exactly on p.
void put_vertex_at(Triangle& t, int i, const Vec3& p) {
  const Vec3 by = p - t.v[static_cast<std::size_t>(i)];
  for (Vec3& v : t.v) v = translated(v, by);
  t.v[static_cast<std::size_t>(i)] = p;
}

}  // namespace

void place_against_face(ObbObbInput& in, ValueSource& v, bool nudged) {
  const int k = static_cast<int>(v.choices().draw(3));
  const Vec3 n = in.a.axes.col[k];
  double rb = 0;
  for (int j = 0; j < 3; ++j) rb += in.b.half[j] * std::fabs(dot(n, in.b.axes.col[j]));
  double reach = in.a.half[k] + rb;
  if (nudged) reach = v.nudge(reach);
  const double sign = v.choices().chance(50) ? -1.0 : 1.0;
  Vec3 c = in.a.center + (sign * reach) * n;
  for (int i = 1; i < 3; ++i) {
    const int j = (k + i) % 3;
    const double along = v.choices().chance(50) ? 0.0 : in.a.half[j] * (v.choices().chance(50) ? 1.0 : 0.5);
    c = c + (v.choices().chance(50) ? along : -along) * in.a.axes.col[j];
  }
  in.b.center = c;
}

void shift_to_touch(KdopKdopInput& in, ValueSource& v, bool nudged) {
  const auto dirs = kdop_directions(in.k);
  if (dirs.empty() || in.a.empty() || in.b.empty()) return;
  const KdopDirection d = dirs[v.choices().draw(dirs.size())];
  const Vec3 dir{static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z)};
  double a_max = -INFINITY, b_min = INFINITY;
  for (const Vec3& p : in.a) a_max = std::max(a_max, dot(dir, p));
  for (const Vec3& p : in.b) b_min = std::min(b_min, dot(dir, p));
  double shift = a_max - b_min;
  if (nudged) shift = v.nudge(shift);
  const int axis = d.x != 0 ? 0 : (d.y != 0 ? 1 : 2);
  for (Vec3& p : in.b) p[axis] += shift * dir[axis];
}

void touch_at_vertices(MeshPair& m, Choices& c) {
  const Mesh &a = *m.a.mesh, &b = *m.b.mesh;
  if (a.vertices.empty() || b.vertices.empty()) return;
  const Vec3 on_a = apply(m.pose_a, a.vertices[c.draw(a.vertices.size())]);
  const Vec3 on_b = apply(m.pose_b, b.vertices[c.draw(b.vertices.size())]);
  m.pose_b.translation = m.pose_b.translation + (on_a - on_b);
}

void make_touching(Input& input, ValueSource& v) {
  Choices& c = v.choices();
  std::visit(
      [&](auto& in) {
        using T = std::decay_t<decltype(in)>;
        if constexpr (std::is_same_v<T, RayAabbInput>) {
          const Vec3 p = detail::draw_boundary_point(v, in.box);
          if (in.ray.dir == Vec3{}) in.ray.dir = {1, 0, 0};
          const double t = std::ldexp(1.0, v.small_int(4));
          in.ray.origin = p - t * in.ray.dir;
          if (c.chance(30)) in.ray.tmax = t;  // a segment that ends on the boundary
        } else if constexpr (std::is_same_v<T, SphereSphereInput>) {
          Vec3 offset;
          offset[static_cast<int>(c.draw(3))] = (c.chance(50) ? -1.0 : 1.0) * (in.a.radius + in.b.radius);
          in.b.center = in.a.center + offset;
        } else if constexpr (std::is_same_v<T, AabbAabbInput>) {
          const int k = static_cast<int>(c.draw(3));
          const double extent = in.b.hi[k] - in.b.lo[k];
          if (c.chance(50)) {
            in.b.lo[k] = in.a.hi[k], in.b.hi[k] = in.a.hi[k] + extent;
          } else {
            in.b.hi[k] = in.a.lo[k], in.b.lo[k] = in.a.lo[k] - extent;
          }
        } else if constexpr (std::is_same_v<T, KdopKdopInput>) {
          shift_to_touch(in, v, false);
        } else if constexpr (std::is_same_v<T, ObbObbInput>) {
          place_against_face(in, v, false);
        } else if constexpr (std::is_same_v<T, TriAabbInput>) {
          put_vertex_at(in.tri, static_cast<int>(c.draw(3)), detail::draw_boundary_point(v, in.box));
        } else if constexpr (std::is_same_v<T, TriObbInput>) {
          const Vec3 local = detail::draw_boundary_point(v, Aabb{-in.box.half, in.box.half});
          put_vertex_at(in.tri, static_cast<int>(c.draw(3)), in.box.center + in.box.axes * local);
        } else if constexpr (std::is_same_v<T, MeshMeshInput> || std::is_same_v<T, MeshMeshFirstInput>) {
          touch_at_vertices(in.meshes, c);
        } else if constexpr (std::is_same_v<T, BroadphaseInput>) {
          // Two boxes of a frame: the second put face to face against the first on one axis.
          if (in.frames.empty() || in.frames[0].size() < 2) return;
          auto& frame = in.frames[c.draw(in.frames.size())];
          const std::size_t i = c.draw(frame.size()), j = c.draw(frame.size());
          if (i == j || !frame[i] || !frame[j]) return;
          AabbAabbInput pair{*frame[i], *frame[j]};
          Input as_pair = pair;
          make_touching(as_pair, v);
          frame[j] = std::get<AabbAabbInput>(as_pair).b;
        } else if constexpr (std::is_same_v<T, RayMeshInput>) {
          // Aimed at a vertex of a face, ending there.
          const Triangle t = in.mesh.mesh->triangle(c.draw(in.mesh.mesh->size()));
          in.ray.dir = t.v[c.draw(3)] - in.ray.origin;
          in.ray.tmin = 0, in.ray.tmax = 1;
        } else if constexpr (std::is_same_v<T, MovingObbInput>) {
          // Placed face to face at rest, then moved back so that they meet at t = 1/2.
          ObbObbInput boxes{in.a.box, in.b.box};
          place_against_face(boxes, v, false);
          in.b.box.center = boxes.b.center - 0.5 * (in.b.velocity - in.a.velocity);
        } else {
          const int i = static_cast<int>(c.draw(3));
          const Vec3 target = c.chance(50) ? in.a.v[static_cast<std::size_t>(i)]
                                           : 0.5 * (in.a.v[static_cast<std::size_t>(i)] + in.a.v[static_cast<std::size_t>((i + 1) % 3)]);
          put_vertex_at(in.b, static_cast<int>(c.draw(3)), target);
        }
      },
      input);
}

}  // namespace cc::harness
