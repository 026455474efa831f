// The tri_aabb kind: a vertex exactly on a corner, edge or face of the box; triangles in the
// plane of a face; degenerate triangles (segments, points); point and segment boxes in the
// triangle's plane; slivers in the regimes of test_triangle_aabb's bound slid to an exact margin.
// The library's call, and what its cases are.
#include "harness/kinds/tri_aabb.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "collide/record_sink.h"
#include "collide/sat_bound.h"
#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"
#include "harness/generation/rotation.h"
#include "harness/generation/touch.h"
#include "harness/generation/triangles.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

// A triangle and a box at an exact margin in the regimes of test_triangle_aabb's bound: boxes of
// aspect ratio up to 2^40 far from the origin, slivers nearly coplanar with a face or nearly
// parallel to an edge.
TriAabbInput tri_aabb_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const double size = draw_size(v);
  const Vec3 offset = draw_far_offset(v, size);
  const Vec3 center = v.point() + offset, half = draw_aspect_extents(v, size);
  const Aabb box{center - half, center + half};
  const Mat3 frame = frame_against(v, Mat3::identity());
  const Triangle t = triangle_in_regime(v, std::ldexp(size, v.small_int(20)), frame);
  const Vec3 w = along_an_axis_or_any(v, Mat3::identity());
  const double box_reach = std::fabs(half.x * w.x) + std::fabs(half.y * w.y) + std::fabs(half.z * w.z);
  return slid_to_the_bound<TriAabbInput>(v, options, t, 0.5 * (box.lo + box.hi), box_reach, w,
                                         [&box](const Triangle& moved) { return TriAabbInput{moved, box}; });
}

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "just overlapping", "segment triangle", "point triangle", "sliver", "flat box",
    "point box", "in a face's plane", "nearly in a face's plane", "edge nearly parallel to an axis",
    "far vertex not last", "far from the origin"};

constexpr BoundTerm kBoundTerms[] = {{"test_triangle_aabb", "axis", "projection"}, {"test_triangle_aabb", "axis", "total"}};

}  // namespace

Answer Query<TriAabbInput>::ask(const TriAabbInput& in) { return Answer::of(test_triangle_aabb(in.tri, in.box)); }

TriAabbInput Query<TriAabbInput>::generate(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return tri_aabb_at_the_bound(v, options);
  TriAabbInput in;
  in.box = draw_aabb(v, options);
  if (v.choices().chance(15)) {  // a flat configuration: a point or segment box in the triangle's plane
    const int k = collapse(v, in.box);
    in.tri = triangle_through_flat_box(v, in.box, k);
    return in;
  }
  in.tri = triangle_near_box(v, in.box);
  return in;
}

void Query<TriAabbInput>::touch(TriAabbInput& in, ValueSource& v) {
  put_vertex_at(in.tri, static_cast<int>(v.choices().draw(3)), draw_boundary_point(v, in.box));
}

Features Query<TriAabbInput>::features(const TriAabbInput& in) {
  return {false, parallel_to_axes(in.tri, Mat3::identity()), degenerate(in.tri) || zero_extent(in.box)};
}

std::span<const std::string_view> Query<TriAabbInput>::configurations() { return kConfigurations; }

void Query<TriAabbInput>::recognise(const TriAabbInput& in, Configurations& found) {
  found.margins();
  const Vec3 half = 0.5 * (in.box.hi - in.box.lo), center = 0.5 * (in.box.lo + in.box.hi);
  found.triangle_and_box(in.tri, Mat3::identity(), center);
  found.boxes(half);
  found.far(std::max(max_coordinate(in.tri), max_abs(center)), std::max(max_abs(half), longest_edge(in.tri)));
}

std::span<const BoundTerm> Query<TriAabbInput>::bound_terms() { return kBoundTerms; }

void Query<TriAabbInput>::probe(const TriAabbInput& in, std::vector<bounds::Records>& records) {
  test_triangle_aabb(in.tri, in.box, bounds::next_call(records));
}

}  // namespace cc::harness
