// The tri_obb kind: triangles touching the box at a vertex, in a face's plane, through point and
// segment boxes, built in the box's frame and taken to the world (exact for exactly orthonormal
// axes and simple values, otherwise within a few ULPs), and
// slivers in the regimes of test_triangle_obb's bound (the box's axes also at the
// orthonormality tolerance) slid to an exact margin. The library's call, and what its cases are.
#include "harness/kinds/tri_obb.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "collide/frame_change_bound.h"
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

// A triangle and a box at an exact margin in the regimes of test_triangle_obb's bound: boxes of
// aspect ratio up to 2^40 far from the origin, their axes also at the orthonormality tolerance,
// slivers nearly coplanar with a face or nearly parallel to an edge.
TriObbInput tri_obb_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const double size = draw_size(v);
  const Vec3 offset = draw_far_offset(v, size);
  Obb box{v.point() + offset, draw_aspect_extents(v, size), draw_rotation(v)};
  if (v.choices().chance(60)) box.axes = perturb_to_tolerance(v, box.axes);
  const Mat3 frame = frame_against(v, box.axes);
  const Triangle t = triangle_in_regime(v, std::ldexp(size, v.small_int(20)), frame);
  const Vec3 w = along_an_axis_or_any(v, box.axes);
  return slid_to_the_bound<TriObbInput>(v, options, t, box.center, reach_along(box, w), w,
                                        [&box](const Triangle& moved) { return TriObbInput{moved, box}; });
}

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "just overlapping", "segment triangle", "point triangle", "sliver", "flat box",
    "point box", "in a face's plane", "nearly in a face's plane", "edge nearly parallel to an axis",
    "frame at the tolerance", "far vertex not last", "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {{"test_triangle_obb", "frame change", "rounding"},
                                     {"test_triangle_obb", "frame change", "orthonormality"},
                                     {"test_triangle_obb", "frame change", "total"},
                                     {"test_triangle_obb", "axis", "projection"},
                                     {"test_triangle_obb", "axis", "total"}};

}  // namespace

Answer Query<TriObbInput>::ask(const TriObbInput& in) { return Answer::of(test_triangle_obb(in.tri, in.box)); }

TriObbInput Query<TriObbInput>::generate(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return tri_obb_at_the_bound(v, options);
  TriObbInput in;
  in.box = draw_obb(v, options);
  // Built in the box's frame, then taken to the world: exact for exactly orthonormal axes and
  // simple values, otherwise within a few ULPs of the constructed contact.
  Triangle local;
  if (v.choices().chance(15)) {  // a flat configuration: a point or segment box in the triangle's plane
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

void Query<TriObbInput>::touch(TriObbInput& in, ValueSource& v) {
  const Vec3 local = draw_boundary_point(v, Aabb{-in.box.half, in.box.half});
  put_vertex_at(in.tri, static_cast<int>(v.choices().draw(3)), in.box.center + in.box.axes * local);
}

Features Query<TriObbInput>::features(const TriObbInput& in) {
  return {false, parallel_to_axes(in.tri, in.box.axes),
          degenerate(in.tri) || in.box.half.x == 0 || in.box.half.y == 0 || in.box.half.z == 0};
}

std::span<const std::string_view> Query<TriObbInput>::configurations() { return kConfigurations; }

void Query<TriObbInput>::recognise(const TriObbInput& in, Configurations& found) {
  found.margins();
  found.triangle_and_box(in.tri, in.box.axes, in.box.center);
  found.boxes(in.box.half);
  found.add("frame at the tolerance", off_orthonormal(in.box.axes) >= kAtTheTolerance);
  found.far(std::max(max_coordinate(in.tri), max_abs(in.box.center)), std::max(max_abs(in.box.half), longest_edge(in.tri)));
}

std::span<const BoundTerm> Query<TriObbInput>::bound_terms() { return kBoundTerms; }

void Query<TriObbInput>::probe(const TriObbInput& in, std::vector<bounds::Records>& records) {
  test_triangle_obb(in.tri, in.box, bounds::next_call(records));
}

}  // namespace cc::harness
