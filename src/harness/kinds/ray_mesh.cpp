// The ray_mesh kind: procedural meshes, FCL's env.obj or small soups with degenerate triangles,
// probed by rays aimed at a vertex, at a point on an edge or inside a face (so they touch by
// construction), grazing a face in its plane, parallel to the axes, or at random; as rays, lines
// (tmin = -inf) and segments that end on the target. The library's calls, and what its cases are.
#include "harness/kinds/ray_mesh.h"

#include <algorithm>
#include <cmath>

#include "collide/ray_mesh.h"
#include "collide/ray_mesh_bound.h"
#include "collide/record_sink.h"
#include "harness/formats/mesh_files.h"
#include "harness/generation/meshes.h"
#include "harness/generation/regimes.h"
#include "harness/generation/rotation.h"
#include "harness/generation/triangles.h"
#include "harness/generation/values.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"
#include "harness/model/mesh_collide.h"

namespace cc::harness {
namespace {

// The triangles as a mesh, each with its own three vertices.
Mesh soup_of(const std::vector<Triangle>& triangles) {
  Mesh soup;
  for (const Triangle& t : triangles) {
    const auto first = static_cast<std::uint32_t>(soup.vertices.size());
    soup.vertices.insert(soup.vertices.end(), t.v.begin(), t.v.end());
    soup.faces.push_back({first, first + 1, first + 2});
  }
  return soup;
}

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
    std::vector<Triangle> triangles(1 + c.draw(6));
    for (Triangle& t : triangles) t = draw_triangle(v);
    return triangles_mesh(soup_of(triangles));
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

// A small soup of slivers far from the origin, and a ray at an exact margin of it in the regimes
// of intersect_ray_triangle's and ray_mesh's bounds: from up to 2^40 times the soup's size away
// or from very near, nearly parallel to a face (grazing), with negative parameters (the soup
// behind the origin on a line); slid off the face until it grazes the soup.
RayMeshInput ray_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  const Vec3 offset = draw_far_offset(v, size);
  const Vec3 center = v.point() + offset;
  std::vector<Triangle> triangles(1 + c.draw(4));
  const Mat3 frame = draw_rotation(v);
  for (Triangle& t : triangles) {
    const Mat3 tilted = c.chance(50) ? frame : nearly_parallel(v, frame);
    t = translated(triangle_in_regime(v, std::ldexp(size, v.small_int(3)), tilted), center);
  }
  const Mesh soup = soup_of(triangles);
  RayMeshInput in;
  in.mesh = triangles_mesh(soup);
  in.library = draw_library(c, false);
  const Triangle face = triangles[c.draw(triangles.size())];
  const Vec3 target = target_on(face, c);
  const Vec3 normal = cross(face.v[1] - face.v[0], face.v[2] - face.v[0]);
  Vec3 d = draw_direction(v);
  if (c.chance(40)) {  // nearly in the face's plane: grazing
    const Vec3 direction = draw_direction(v);
    const Vec3 nudge = std::ldexp(1.0, -static_cast<int>(8 + c.draw(45))) * direction;
    d = (face.v[c.draw(3)] - target) + nudge;
    if (!(max_abs(d) > 0)) d = draw_direction(v);  // GCOVR_EXCL_BR_LINE: only if the nudge cancels exactly
  }
  const double distance = std::ldexp(1.0, v.small_int(40)) * size / max_abs(d);
  const bool behind = c.chance(25);
  in.ray = {behind ? target + distance * d : target - distance * d, d, behind ? -INFINITY : 0, INFINITY};
  Vec3 w = c.chance(60) && max_abs(normal) > 0 ? normal : draw_direction(v);
  double reach = 0;
  for (const Vec3& p : soup.vertices) reach = std::max(reach, std::fabs(dot(p - target, w)));
  const auto placed = [&in, &w](double s) {
    RayMeshInput out = in;
    out.ray.origin = in.ray.origin + s * w;
    return out;
  };
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, 2 * reach / dot(w, w) + size / std::sqrt(dot(w, w)),
                            draw_margin_target(c), options, 0);
  return placed(s);
}

Answer ray_answer(const RayMeshHit& h, bool with_t) {
  Answer a = Answer::of(h.hit);
  if (!h.hit) return a;
  if (with_t) a.params = {h.t};
  a.pairs = {{h.face, 0}};
  return a;
}

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "grazing a face", "parallel to a face", "from far away", "negative parameters",
    "zero direction", "degenerate face", "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {{"intersect_ray_triangle", "slab", "projection"},
                                     {"intersect_ray_triangle", "slab", "speed"},
                                     {"intersect_ray_triangle", "slab", "total"},
                                     {"intersect_ray_triangle", "triangle parameter", "rounding"},
                                     {"intersect_ray_triangle", "triangle parameter", "total"},
                                     {"ray_mesh_closest", "face hit", "origin"},
                                     {"ray_mesh_closest", "face hit", "mesh"},
                                     {"ray_mesh_closest", "face hit", "total"}};

}  // namespace

Answer Query<RayMeshInput>::ask(const RayMeshInput& in) {
  return ray_answer(library_ray_mesh(in.mesh.mesh, in.library, in.ray, false), true);
}

const std::vector<Party<RayMeshInput>>& Query<RayMeshInput>::library_parties() {
  static const std::vector<Party<RayMeshInput>> parties = {
      {"library.ray_mesh_any", band,
       [](const RayMeshInput& in) { return answered(ray_answer(library_ray_mesh(in.mesh.mesh, in.library, in.ray, true), false)); }},
      {"library.ray_mesh_brute_force", band,
       [](const RayMeshInput& in) { return answered(ray_answer(ray_mesh_brute_force(*in.mesh.mesh, in.ray), true)); }}};
  return parties;
}

RayMeshInput Query<RayMeshInput>::generate(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  if (c.chance(35)) return ray_at_the_bound(v, options);
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
      case 0: r.origin = with_one_component(r.origin, NAN, c); break;
      case 1: r.dir = with_one_component(r.dir, INFINITY, c); break;
      default: std::swap(r.tmin, r.tmax), r.tmin = 1, r.tmax = 0;
    }
  }
  return in;
}

void Query<RayMeshInput>::touch(RayMeshInput& in, ValueSource& v) {
  Choices& c = v.choices();
  const Triangle t = in.mesh.mesh->triangle(c.draw(in.mesh.mesh->size()));
  in.ray.dir = t.v[c.draw(3)] - in.ray.origin;
  in.ray.tmin = 0, in.ray.tmax = 1;
}

Features Query<RayMeshInput>::features(const RayMeshInput& in) {
  Features f;
  const Mesh& mesh = *in.mesh.mesh;
  for (int k = 0; k < 3; ++k) f.parallel |= in.ray.dir[k] == 0;
  f.degenerate = is_zero(in.ray.dir);
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Vec3 n = normal(mesh.triangle(i));
    f.degenerate |= is_zero(n);
    f.parallel |= !is_zero(n) && dot(n, in.ray.dir) == 0;
  }
  return f;
}

std::span<const std::string_view> Query<RayMeshInput>::configurations() { return kConfigurations; }

void Query<RayMeshInput>::recognise(const RayMeshInput& in, Configurations& found) {
  found.margins();
  const Mesh& mesh = *in.mesh.mesh;
  bool grazing = false, par = false, degenerate_face = false;
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Vec3 n = normal(mesh.triangle(i));
    degenerate_face |= n == Vec3{};
    const double s = length(n) > 0 && length(in.ray.dir) > 0 ? std::fabs(dot(n, in.ray.dir)) / (length(n) * length(in.ray.dir)) : 1;
    grazing |= s > 0 && s <= kNearlyParallel;
    par |= length(n) > 0 && length(in.ray.dir) > 0 && dot(n, in.ray.dir) == 0;
  }
  for (const Vec3& p : mesh.vertices) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  const double size = max_abs(hi - lo);
  double gap = 0;
  for (int k = 0; k < 3; ++k) gap = std::max({gap, lo[k] - in.ray.origin[k], in.ray.origin[k] - hi[k]});
  found.add("grazing a face", grazing);
  found.add("parallel to a face", par);
  found.add("degenerate face", degenerate_face);
  found.add("from far away", size > 0 && gap >= kFar * size);
  found.negative_parameters();
  found.add("zero direction", in.ray.dir == Vec3{});
  found.far(std::max(max_abs(lo), max_abs(hi)), size);
}

std::span<const BoundTerm> Query<RayMeshInput>::bound_terms() { return kBoundTerms; }

void Query<RayMeshInput>::probe(const RayMeshInput& in, std::vector<bounds::Records>& records) {
  with_bv_type(in.library.bv, [&]<class BV>() {
    const auto bvh = cached_bvh<BV>(in.mesh.mesh, in.library.build);
    ray_mesh_closest(*bvh, in.ray, bounds::next_call(records));
  });
}

}  // namespace cc::harness
