// Drawing a case as SVG: the shapes in three orthographic views (x-y, x-z, y-z), and the
// projections of both shapes onto the deciding axis as two intervals on a line.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "tool/cases.h"

namespace cc::tool {
namespace {

using namespace harness;

struct Segment {
  Vec3 p, q;
  int shape;  // 0: A, 1: B
};
struct Circle {
  Vec3 c;
  double r;
  int shape;
};

struct Scene {
  std::vector<Segment> segments;
  std::vector<Circle> circles;
  std::vector<std::pair<Vec3, int>> points;

  void box(const Vec3& center, const std::array<Vec3, 3>& half_edges, int shape) {
    std::array<Vec3, 8> corner;
    for (int i = 0; i < 8; ++i) {
      Vec3 p = center;
      for (int k = 0; k < 3; ++k) p = p + ((i >> k) & 1 ? 1.0 : -1.0) * half_edges[static_cast<std::size_t>(k)];
      corner[static_cast<std::size_t>(i)] = p;
    }
    for (int i = 0; i < 8; ++i) {
      for (int k = 0; k < 3; ++k) {
        if (!((i >> k) & 1)) segments.push_back({corner[static_cast<std::size_t>(i)], corner[static_cast<std::size_t>(i | (1 << k))], shape});
      }
    }
  }
  void aabb(const Aabb& b, int shape) {
    box(0.5 * (b.lo + b.hi), {Vec3{0.5 * (b.hi.x - b.lo.x), 0, 0}, Vec3{0, 0.5 * (b.hi.y - b.lo.y), 0},
                              Vec3{0, 0, 0.5 * (b.hi.z - b.lo.z)}}, shape);
  }
  void obb(const Obb& b, int shape) {
    box(b.center, {b.half.x * b.axes.col[0], b.half.y * b.axes.col[1], b.half.z * b.axes.col[2]}, shape);
  }
  void triangle(const Triangle& t, int shape) {
    for (int i = 0; i < 3; ++i) {
      segments.push_back({t.v[static_cast<std::size_t>(i)], t.v[static_cast<std::size_t>((i + 1) % 3)], shape});
      points.push_back({t.v[static_cast<std::size_t>(i)], shape});  // a degenerate triangle stays visible
    }
  }
};

Scene scene_of(const Input& input) {
  Scene s;
  std::visit(
      [&s](const auto& in) {
        using T = std::decay_t<decltype(in)>;
        if constexpr (std::is_same_v<T, RayAabbInput>) {
          s.aabb(in.box, 1);
          const double reach = std::max({max_abs(in.box.lo - in.ray.origin), max_abs(in.box.hi - in.ray.origin), 1.0}) * 2;
          const double len = std::max(max_abs(in.ray.dir), 1e-300);
          const double t0 = std::max(in.ray.tmin, -reach / len), t1 = std::min(in.ray.tmax, reach / len);
          s.segments.push_back({in.ray.origin + t0 * in.ray.dir, in.ray.origin + t1 * in.ray.dir, 0});
          s.points.push_back({in.ray.origin, 0});
        } else if constexpr (std::is_same_v<T, SphereSphereInput>) {
          s.circles.push_back({in.a.center, in.a.radius, 0});
          s.circles.push_back({in.b.center, in.b.radius, 1});
        } else if constexpr (std::is_same_v<T, AabbAabbInput>) {
          s.aabb(in.a, 0);
          s.aabb(in.b, 1);
        } else if constexpr (std::is_same_v<T, KdopKdopInput>) {
          for (const Vec3& p : in.a) s.points.push_back({p, 0});
          for (const Vec3& p : in.b) s.points.push_back({p, 1});
        } else if constexpr (std::is_same_v<T, ObbObbInput>) {
          s.obb(in.a, 0);
          s.obb(in.b, 1);
        } else if constexpr (std::is_same_v<T, TriAabbInput>) {
          s.triangle(in.tri, 0);
          s.aabb(in.box, 1);
        } else if constexpr (std::is_same_v<T, TriObbInput>) {
          s.triangle(in.tri, 0);
          s.obb(in.box, 1);
        } else if constexpr (std::is_same_v<T, TriTriInput>) {
          s.triangle(in.a, 0);
          s.triangle(in.b, 1);
        } else if constexpr (std::is_same_v<T, BroadphaseInput>) {  // the last frame's boxes
          if (in.frames.empty()) return;
          for (const auto& box : in.frames.back()) {
            if (box) s.aabb(*box, 0);
          }
        } else if constexpr (std::is_same_v<T, RayMeshInput>) {  // the ray and the first 400 faces
          const Mesh& mesh = *in.mesh.mesh;
          double reach = 1;
          for (std::size_t f = 0; f < std::min<std::size_t>(mesh.size(), 400); ++f) {
            s.triangle(mesh.triangle(f), 1);
            for (const Vec3& p : mesh.triangle(f).v) reach = std::max(reach, 2 * max_abs(p - in.ray.origin));
          }
          const double len = std::max(max_abs(in.ray.dir), 1e-300);
          const double t0 = std::max(in.ray.tmin, -reach / len), t1 = std::min(in.ray.tmax, reach / len);
          s.segments.push_back({in.ray.origin + t0 * in.ray.dir, in.ray.origin + t1 * in.ray.dir, 0});
          s.points.push_back({in.ray.origin, 0});
        } else if constexpr (std::is_same_v<T, MovingObbInput>) {  // at the start and the end of the step
          s.obb(in.a.box, 0);
          s.obb({in.a.box.center + in.a.velocity, in.a.box.half, in.a.box.axes}, 0);
          s.obb(in.b.box, 1);
          s.obb({in.b.box.center + in.b.velocity, in.b.box.half, in.b.box.axes}, 1);
        } else {  // meshes, placed in the world (the first 200 triangles of each)
          const MeshPair& m = in.meshes;
          for (int side = 0; side < 2; ++side) {
            const Mesh& mesh = side == 0 ? *m.a.mesh : *m.b.mesh;
            const RigidTransform& pose = side == 0 ? m.pose_a : m.pose_b;
            for (std::size_t f = 0; f < std::min<std::size_t>(mesh.size(), 200); ++f) {
              Triangle t = mesh.triangle(f);
              for (Vec3& p : t.v) p = apply(pose, p);
              s.triangle(t, side);
            }
          }
        }
      },
      input);
  return s;
}

const char* const kColour[] = {"#1f6fb4", "#e07b00"};

}  // namespace

std::string svg_of(const Input& input, const Explanation& why) {
  const Scene s = scene_of(input);
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  const auto grow = [&](const Vec3& p, double r) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k])) continue;
      lo[k] = std::min(lo[k], p[k] - r);
      hi[k] = std::max(hi[k], p[k] + r);
    }
  };
  for (const Segment& g : s.segments) grow(g.p, 0), grow(g.q, 0);
  for (const Circle& c : s.circles) grow(c.c, std::isfinite(c.r) ? std::fabs(c.r) : 0);
  for (const auto& [p, shape] : s.points) grow(p, 0);
  for (int k = 0; k < 3; ++k) {
    if (!(lo[k] <= hi[k])) lo[k] = -1, hi[k] = 1;
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300}) * 1.1;
  const Vec3 mid = 0.5 * (lo + hi);

  constexpr int kPanel = 320, kMargin = 24;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 3 * kPanel << "\" height=\"" << kPanel + 140
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const int views[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  const char* const axis_name = "xyz";
  for (int v = 0; v < 3; ++v) {
    const int u = views[v][0], w = views[v][1];
    const double ox = v * kPanel;
    const auto px = [&](const Vec3& p) {
      return ox + kMargin + (p[u] - mid[u] + extent / 2) / extent * (kPanel - 2 * kMargin);
    };
    const auto py = [&](const Vec3& p) {
      return kPanel - kMargin - (p[w] - mid[w] + extent / 2) / extent * (kPanel - 2 * kMargin);
    };
    svg << "<rect x=\"" << ox + 2 << "\" y=\"2\" width=\"" << kPanel - 4 << "\" height=\"" << kPanel - 4
        << "\" fill=\"none\" stroke=\"#ccc\"/>\n";
    svg << "<text x=\"" << ox + 8 << "\" y=\"16\">" << axis_name[u] << " (right), " << axis_name[w]
        << " (up); <tspan fill=\"" << kColour[0] << "\">A</tspan>, <tspan fill=\"" << kColour[1] << "\">B</tspan></text>\n";
    for (const Segment& g : s.segments) {
      svg << "<line x1=\"" << px(g.p) << "\" y1=\"" << py(g.p) << "\" x2=\"" << px(g.q) << "\" y2=\"" << py(g.q)
          << "\" stroke=\"" << kColour[g.shape] << "\" stroke-width=\"1.5\"/>\n";
    }
    for (const Circle& c : s.circles) {
      svg << "<circle cx=\"" << px(c.c) << "\" cy=\"" << py(c.c) << "\" r=\""
          << std::fabs(c.r) / extent * (kPanel - 2 * kMargin) << "\" fill=\"none\" stroke=\"" << kColour[c.shape] << "\"/>\n";
    }
    for (const auto& [p, shape] : s.points) {
      svg << "<circle cx=\"" << px(p) << "\" cy=\"" << py(p) << "\" r=\"3\" fill=\"" << kColour[shape] << "\"/>\n";
    }
  }
  // The deciding axis as a number line with both projected intervals.
  const double y0 = kPanel + 40;
  svg << "<text x=\"10\" y=\"" << y0 - 18 << "\">" << (why.deciding.empty() ? std::string("(no deciding axis)") : why.deciding)
      << "</text>\n";
  if (why.axis) {
    const double l = std::min(why.a_lo, why.b_lo), h = std::max(why.a_hi, why.b_hi);
    const double span = std::max(h - l, 1e-300) * 1.2, centre = 0.5 * (l + h);
    const auto x = [&](double t) { return 40 + (t - centre + span / 2) / span * (3 * kPanel - 80); };
    const auto bar = [&](double a, double b, int shape, double y) {
      svg << "<rect x=\"" << x(a) << "\" y=\"" << y << "\" width=\"" << std::max(x(b) - x(a), 1.0)
          << "\" height=\"12\" fill=\"" << kColour[shape] << "\" opacity=\"0.7\"/>\n";
    };
    bar(why.a_lo, why.a_hi, 0, y0);
    bar(why.b_lo, why.b_hi, 1, y0 + 18);
    char label[200];
    std::snprintf(label, sizeof label, "axis (%.6g, %.6g, %.6g): A [%.10g, %.10g] (blue), B [%.10g, %.10g] (orange)",
                  why.axis->x, why.axis->y, why.axis->z, why.a_lo, why.a_hi, why.b_lo, why.b_hi);
    svg << "<text x=\"10\" y=\"" << y0 + 52 << "\">" << label << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace cc::tool
