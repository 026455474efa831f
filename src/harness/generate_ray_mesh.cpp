// Generator for ray_mesh: procedural meshes, FCL's env.obj or small soups with degenerate
// triangles, probed by rays aimed at a vertex, at a point on an edge or inside a face (so they
// touch by construction), grazing a face in its plane, parallel to the axes, or at random; as
// rays, lines (tmin = -inf) and segments that end on the target.
#include <cmath>

#include "harness/generate_detail.h"
#include "harness/mesh_files.h"

namespace cc::harness::detail {
namespace {

MeshRef draw_mesh(ValueSource& v, const GenerateOptions& options, bool& big) {
  Choices& c = v.choices();
  big = false;
  if (c.chance(15)) {
    if (const auto env = find_mesh_file("env.obj", options.mesh_folder)) {
      MeshRef m;
      m.source = MeshRef::Source::file;
      m.file = "meshes/env.obj";
      m.mesh = load_mesh_file(*env);
      big = true;
      return m;
    }
  }
  if (c.chance(30)) {
    Mesh soup;
    const std::uint32_t n = 1 + static_cast<std::uint32_t>(c.draw(6));
    for (std::uint32_t i = 0; i < n; ++i) {
      const Triangle t = draw_triangle(v);
      soup.vertices.insert(soup.vertices.end(), t.v.begin(), t.v.end());
      soup.faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    return triangles_mesh(std::move(soup));
  }
  return procedural_mesh(draw_recipe(c, std::ldexp(1.0, v.small_int(4))));
}

// A point of the triangle: a vertex, an edge's midpoint, or its centroid-like inside point.
Vec3 target_on(const Triangle& t, Choices& c) {
  const int i = static_cast<int>(c.draw(3));
  switch (c.draw(3)) {
    case 0: return t.v[static_cast<std::size_t>(i)];
    case 1: return 0.5 * (t.v[static_cast<std::size_t>(i)] + t.v[static_cast<std::size_t>((i + 1) % 3)]);
    default: return 0.25 * t.v[0] + 0.25 * t.v[1] + 0.5 * t.v[2];
  }
}

}  // namespace

RayMeshInput generate_ray_mesh(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  RayMeshInput in;
  bool big = false;
  in.mesh = draw_mesh(v, options, big);
  in.library = draw_library(c, big);
  const Mesh& mesh = *in.mesh.mesh;
  const Triangle face = mesh.triangle(c.draw(mesh.size()));
  const Vec3 target = target_on(face, c);
  Ray& r = in.ray;
  r.tmin = 0;
  r.tmax = INFINITY;
  switch (c.draw(5)) {
    case 0: {  // grazing: along an edge of the face, from outside it
      const int i = static_cast<int>(c.draw(3));
      r.dir = face.v[static_cast<std::size_t>((i + 1) % 3)] - face.v[static_cast<std::size_t>(i)];
      r.origin = face.v[static_cast<std::size_t>(i)] - r.dir;
      break;
    }
    case 1: {  // parallel to an axis, through the target
      r.dir = {};
      r.dir[static_cast<int>(c.draw(3))] = c.chance(50) ? 1.0 : -1.0;
      r.origin = target - std::ldexp(1.0, v.small_int(3)) * r.dir;
      break;
    }
    case 2:  // at random
      r.origin = v.point();
      r.dir = v.point();
      break;
    default: {  // from a random point at the target
      r.origin = v.point();
      r.dir = target - r.origin;
    }
  }
  switch (c.draw(5)) {
    case 0: r.tmin = -INFINITY; break;                    // a line
    case 1: r.tmax = 1; break;                            // a segment ending on the target (when aimed)
    case 2: r.tmax = std::ldexp(1.0, -v.small_int(4)); break;  // a segment that may stop short
    default: break;
  }
  if (options.out_of_contract && c.chance(10)) {
    switch (c.draw(3)) {
      case 0: r.origin[static_cast<int>(c.draw(3))] = NAN; break;
      case 1: r.dir[static_cast<int>(c.draw(3))] = INFINITY; break;
      default: std::swap(r.tmin, r.tmax), r.tmin = 1, r.tmax = 0;
    }
  }
  return in;
}

}  // namespace cc::harness::detail
