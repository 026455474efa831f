// The per-kind generators behind generate() (internal to the harness).
#pragma once

#include <utility>
#include <vector>

#include "harness/generation/generate.h"
#include "harness/generation/margin_bisection.h"
#include "harness/generation/values.h"

namespace cc::harness::detail {

RayAabbInput generate_ray_aabb(ValueSource& values, const GenerateOptions& options);
SphereSphereInput generate_sphere_sphere(ValueSource& values, const GenerateOptions& options);
AabbAabbInput generate_aabb_aabb(ValueSource& values, const GenerateOptions& options);
KdopKdopInput generate_kdop_kdop(ValueSource& values, const GenerateOptions& options);
ObbObbInput generate_obb_obb(ValueSource& values, const GenerateOptions& options);
TriAabbInput generate_tri_aabb(ValueSource& values, const GenerateOptions& options);
TriObbInput generate_tri_obb(ValueSource& values, const GenerateOptions& options);
TriTriInput generate_tri_tri(ValueSource& values, const GenerateOptions& options);
MeshPair generate_meshes(ValueSource& values, const GenerateOptions& options);
BroadphaseInput generate_broadphase(ValueSource& values, const GenerateOptions& options);
RayMeshInput generate_ray_mesh(ValueSource& values, const GenerateOptions& options);
MovingObbInput generate_moving_obb(ValueSource& values, const GenerateOptions& options);
/// A hierarchy for the library: any volume, build and walk; with `few`, one of a few per volume
/// type (for FCL's big meshes, so that the campaign's workers build each once).
LibraryBvh draw_library(Choices& choices, bool few);
/// A procedural mesh of about the given size.
ProceduralMesh draw_recipe(Choices& choices, double size);


/// A box [lo, lo + extent], extents often 0; out of contract sometimes inverted.
Aabb draw_aabb(ValueSource& values, const GenerateOptions& options);
/// A point of the box's boundary: a corner, a point on an edge or on a face.
Vec3 draw_boundary_point(ValueSource& values, const Aabb& box);
/// An OBB with a rotation from draw_rotation (or, out of contract, a non-orthonormal one).
Obb draw_obb(ValueSource& values, const GenerateOptions& options);
/// A triangle: generic, or degenerate (a segment, a point).
Triangle draw_triangle(ValueSource& values);
/// A triangle touching the box at one vertex (a corner, a point of an edge or of a face) or a few
/// ULPs off it on one axis, its other vertices outside the box, away from its centre.
Triangle triangle_touching_at_a_vertex(ValueSource& values, const Aabb& box);

// The regimes of the certified error bounds, for the bound-reaching constructions
// (generate_regimes.cpp).

/// A length: 2^k for k in [-20, 20], or a generic multiple of one.
double draw_size(ValueSource& values);
/// Half extents with aspect ratios up to 2^40 (size on some axes, down to size 2^-40 on
/// others), sometimes 0 (flat boxes, segments, points).
Vec3 draw_aspect_extents(ValueSource& values, double size);
/// A generic direction, not normalised (components up to 2 in magnitude, some 0).
Vec3 draw_direction(ValueSource& values);
/// A translation up to 2^40 times `size` in a generic direction (or none).
Vec3 draw_far_offset(ValueSource& values, double size);
/// Whether the matrix's axes are orthonormal to within kObbOrthonormalTolerance, checked in
/// floating point with room for that check's rounding.
bool within_tolerance(const Mat3& m);
/// The rotation with its axes moved off orthonormal by 0.5 to 0.7 of kObbOrthonormalTolerance
/// (every entry of the Gram matrix), inside the tolerance.
Mat3 perturb_to_tolerance(ValueSource& values, const Mat3& rotation);
/// `base` turned by an angle of 2^-8 to 2^-52 about a generic axis: nearly parallel axes.
Mat3 nearly_parallel(ValueSource& values, const Mat3& base);
/// Two boxes with a common centre in the regimes of test_obb_obb's bound: aspect ratios up to
/// 2^40, sizes up to 2^40 apart, far from the origin, frames at the orthonormality tolerance or
/// nearly parallel (generate_boxes.cpp).
ObbObbInput obb_pair_in_regime(ValueSource& values);
/// A direction to slide b along: a face normal of either box, an edge-edge axis, or any.
Vec3 slide_direction(ValueSource& values, const Obb& a, const Obb& b);
/// The half width of the box's projection onto w (w not normalised).
double reach_along(const Obb& box, const Vec3& w);
/// The triangle's vertices in one of their six orders.
void shuffle_vertices(Choices& choices, Triangle& t);
/// A triangle in the regimes of the triangle tests' bounds, of about the given size, about the
/// plane of the first two columns of `frame` (its first edge along the first column): a sliver of
/// aspect ratio up to 2^40, in that plane, tilted out of it by 2^-8 to 2^-52 (nearly coplanar,
/// nearly parallel edges), or at any angle; its vertices in any order (generate_triangles.cpp).
Triangle triangle_in_regime(ValueSource& values, double size, const Mat3& frame);
/// The triangle moved by `by`.
Triangle translated(const Triangle& t, const Vec3& by);
/// The items in any order (the constructions build them in a fixed one).
template <class T>
void shuffle(Choices& choices, std::vector<T>& items) {
  for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[choices.draw(i)]);
}

/// Where a bound-reaching construction is placed: an exact margin (ExactVerdict units) and the
/// side of it. Mostly touching (0, either side), else apart or overlapping by 2^-40 to 2^-53 of
/// the scale: a small multiple of the library's error bounds, both signs.
struct MarginTarget {
  double margin;
  Side side;
};
MarginTarget draw_margin_target(Choices& choices);

/// The parameter of `family` at the target margin, from a case that overlaps (s_overlap) and one
/// that is apart (s_apart), by exact bisection with options.exact; `fallback` without it or when
/// no crossing is found.
double place_at(const Family& family, double s_overlap, double s_apart, const MarginTarget& target,
                const GenerateOptions& options, double fallback);

}  // namespace cc::harness::detail
