// The tri_tri kind: shared vertices, a vertex on the other triangle's edge, coplanar triangles
// (or one vertex a few ULPs off the plane), a triangle moved by a few ULPs, edges crossing at
// their middles, degenerate triangles, and slivers in the regimes of test_triangle_triangle's
// bound slid to an exact margin. The library's call, and what its cases are.
#include "harness/kinds/tri_tri.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "collide/independence_bound.h"
#include "collide/record_sink.h"
#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"
#include "harness/generation/rotation.h"
#include "harness/generation/touch.h"
#include "harness/generation/triangles.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

// Two triangles at an exact margin in the regimes of test_triangle_triangle's bound: slivers far
// from the origin, coplanar or nearly, with edges parallel or nearly, of sizes up to 2^20 apart.
TriTriInput tri_tri_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const double size = draw_size(v);
  const Mat3 frame = draw_rotation(v);
  const Vec3 offset = draw_far_offset(v, size);
  const Vec3 place = v.point() + offset;
  const Triangle a = translated(triangle_in_regime(v, size, frame), place);
  const Mat3 other = v.choices().chance(30) ? frame : (v.choices().chance(60) ? nearly_parallel(v, frame) : draw_rotation(v));
  const Triangle b = triangle_in_regime(v, std::ldexp(size, v.small_int(20)), other);
  const Vec3 w = along_an_axis_or_any(v, frame);
  TriTriInput in = slid_to_the_bound<TriTriInput>(v, options, b, centroid(a), triangle_reach_along(a, w), w,
                                                  [&a](const Triangle& moved) { return TriTriInput{a, moved}; });
  if (v.choices().chance(50)) std::swap(in.a, in.b);
  return in;
}

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "just overlapping", "segment triangle", "point triangle", "sliver", "coplanar",
    "nearly coplanar", "parallel edges", "nearly parallel edges", "far vertex not last", "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {{"test_triangle_triangle", "axis", "projection"},
                                     {"test_triangle_triangle", "axis", "total"},
                                     {"test_triangle_triangle", "coplanarity", "rounding"},
                                     {"test_triangle_triangle", "coplanarity", "total"}};

}  // namespace

Answer Query<TriTriInput>::ask(const TriTriInput& in) { return Answer::of(test_triangle_triangle(in.a, in.b)); }

TriTriInput Query<TriTriInput>::generate(ValueSource& v, const GenerateOptions& options) {
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

void Query<TriTriInput>::touch(TriTriInput& in, ValueSource& v) {
  Choices& c = v.choices();
  const int i = static_cast<int>(c.draw(3));
  const Vec3 target = c.chance(50) ? in.a.v[static_cast<std::size_t>(i)]
                                   : 0.5 * (in.a.v[static_cast<std::size_t>(i)] + in.a.v[static_cast<std::size_t>((i + 1) % 3)]);
  put_vertex_at(in.b, static_cast<int>(c.draw(3)), target);
}

Features Query<TriTriInput>::features(const TriTriInput& in) {
  Features f;
  f.parallel = parallel_edges(in.a, in.b) || parallel(normal(in.a), normal(in.b));
  f.degenerate = degenerate(in.a) || degenerate(in.b);
  return f;
}

std::span<const std::string_view> Query<TriTriInput>::configurations() { return kConfigurations; }

void Query<TriTriInput>::recognise(const TriTriInput& in, Configurations& found) {
  found.margins();
  found.triangle(in.a), found.triangle(in.b);
  found.add("coplanar", coplanar(in.a, in.b));
  found.add("nearly coplanar", nearly_parallel(normal(in.a), normal(in.b)));
  bool par = false, nearly = false;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) par |= parallel(edge(in.a, i), edge(in.b, j)), nearly |= nearly_parallel(edge(in.a, i), edge(in.b, j));
  }
  found.add("parallel edges", par);
  found.add("nearly parallel edges", nearly);
  found.add("far vertex not last", far_vertex_not_last(in.a, centroid(in.b)) || far_vertex_not_last(in.b, centroid(in.a)));
  found.far(std::max(max_coordinate(in.a), max_coordinate(in.b)), std::max(longest_edge(in.a), longest_edge(in.b)));
}

std::span<const BoundTerm> Query<TriTriInput>::bound_terms() { return kBoundTerms; }

void Query<TriTriInput>::probe(const TriTriInput& in, std::vector<bounds::Records>& records) {
  test_triangle_triangle(in.a, in.b, bounds::next_call(records));
}

}  // namespace cc::harness
