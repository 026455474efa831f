#include "harness/formats/drawing.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "harness/model/parts.h"

namespace cc::harness {
namespace {

struct Draw {
  Drawing& out;
  int shape = 0;  // the shape of the next part that draws

  void box(const Vec3& center, const std::array<Vec3, 3>& half_edges, int s) {
    std::array<Vec3, 8> corner;
    for (std::size_t i = 0; i < 8; ++i) {
      Vec3 p = center;
      for (std::size_t k = 0; k < 3; ++k) p = p + ((i >> k) & 1 ? 1.0 : -1.0) * half_edges[k];
      corner[i] = p;
    }
    for (std::size_t i = 0; i < 8; ++i) {
      for (std::size_t k = 0; k < 3; ++k) {
        if (!((i >> k) & 1)) out.segments.push_back({corner[i], corner[i | (std::size_t{1} << k)], s});
      }
    }
  }
  void aabb(const Aabb& b, int s) {
    box(0.5 * (b.lo + b.hi), {Vec3{0.5 * (b.hi.x - b.lo.x), 0, 0}, Vec3{0, 0.5 * (b.hi.y - b.lo.y), 0},
                              Vec3{0, 0, 0.5 * (b.hi.z - b.lo.z)}}, s);
  }
  void obb(const Obb& b, int s) { box(b.center, {b.half.x * b.axes.col[0], b.half.y * b.axes.col[1], b.half.z * b.axes.col[2]}, s); }
  void triangle(const Triangle& t, int s) {
    for (std::size_t i = 0; i < 3; ++i) {
      out.segments.push_back({t.v[i], t.v[(i + 1) % 3], s});
      out.points.push_back({t.v[i], s});  // a degenerate triangle stays visible
    }
  }
  void faces(const Mesh& mesh, const RigidTransform* pose, std::size_t most, int s) {
    for (std::size_t f = 0; f < std::min(mesh.size(), most); ++f) {
      Triangle t = mesh.triangle(f);
      if (pose != nullptr) {
        for (Vec3& p : t.v) p = apply(*pose, p);
      }
      triangle(t, s);
    }
  }

  void at(const Aabb& b, Plain) { aabb(b, shape++); }
  void at(const Obb& b, Plain) { obb(b, shape++); }
  void at(const Sphere& s, Plain) { out.circles.push_back({s.center, s.radius, shape++}); }
  void at(const Triangle& t, Plain) { triangle(t, shape++); }
  void at(const std::vector<Vec3>& points, Plain) {
    for (const Vec3& p : points) out.points.push_back({p, shape});
    ++shape;
  }
  void at(const Ray& r, Plain) { out.rays.push_back({r, shape++}); }
  // A disc and walls lie in the plane z = 0: a wall by its segment and its ends (a pillar stays
  // visible), every part of a list as one shape.
  void at(const Disc& d, Plain) { out.circles.push_back({{d.center.x, d.center.y, 0}, d.radius, shape++}); }
  void wall(const Wall& w, int s) {
    const Vec3 a{w.a.x, w.a.y, 0}, b{w.b.x, w.b.y, 0};
    out.segments.push_back({a, b, s});
    out.points.push_back({a, s});
    out.points.push_back({b, s});
  }
  void at(const Wall& w, Plain) { wall(w, shape++); }
  template <PartList L>
  void at(const L& parts, Plain) {
    const int s = shape;
    for (const auto& part : parts) {
      shape = s;
      at(part, Plain{});
    }
    shape = s + 1;
  }
  void at(const MovingObb& m, Plain) {  // at the start and the end of the step
    obb(m.box, shape);
    obb({m.box.center + m.velocity, m.box.half, m.box.axes}, shape);
    ++shape;
  }
  void at(const MeshRef& m, Plain) { faces(*m.mesh, nullptr, 400, shape++); }
  void at(const MeshPair& m, Plain) {  // placed in the world
    faces(*m.a.mesh, &m.pose_a, 200, shape++);
    faces(*m.b.mesh, &m.pose_b, 200, shape++);
  }
  void at(const BoxFrames& frames, Plain) {  // the last frame's boxes
    if (frames.empty()) return;
    for (const auto& b : frames.back()) {
      if (b) aabb(*b, shape);
    }
    ++shape;
  }
  template <class T, class As>
  void at(const T& value, As) {  // the rest draws nothing of its own (k, the hierarchy)
    if constexpr (HasFields<T>) {
      for_each_field<T>([&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        at(F::of(value), typename F::As{});
      });
    }
  }
};

}  // namespace

void draw_rays(Drawing& d) {
  for (const Drawing::RayLine& line : d.rays) {
    const Ray& r = line.ray;
    double reach = 1;
    for (const Drawing::Segment& g : d.segments) reach = std::max({reach, max_abs(g.p - r.origin), max_abs(g.q - r.origin)});
    for (const Drawing::Point& p : d.points) reach = std::max(reach, max_abs(p.p - r.origin));
    reach *= 2;
    const double len = std::max(max_abs(r.dir), 1e-300);
    const double t0 = std::max(r.tmin, -reach / len), t1 = std::min(r.tmax, reach / len);
    d.segments.push_back({r.origin + t0 * r.dir, r.origin + t1 * r.dir, line.shape});
    d.points.push_back({r.origin, line.shape});
  }
  d.rays.clear();
}

Drawing drawing_of(const Input& input) {
  Drawing d;
  std::visit([&d](const auto& in) { Draw{d}.at(in, Plain{}); }, input);
  return d;
}

}  // namespace cc::harness
