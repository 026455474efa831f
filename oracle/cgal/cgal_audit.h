// CGAL's exact kernel (exact predicates, exact constructions) as a second exact reference, to
// audit oracle/exact with: whether two closed shapes meet, for the shapes CGAL can express, the
// same doubles converted exactly; the slabs of two k-DOPs; where a ray first meets a mesh. This
// unit is the only one that includes CGAL (its headers are slow to compile); exact_audit.h puts
// it to work on the queries.
//
// Every function takes inputs in the library's contract (finite coordinates, boxes not
// inverted, radii and half extents >= 0, an oriented box's axes independent, a ray's tmin < inf
// and tmax > -inf) and throws std::invalid_argument otherwise. Touching is a hit. Degenerate
// shapes are what they span: a collinear triangle the segment between its extreme vertices, a
// box of zero extent a rectangle, a segment or a point.
#pragma once

#include <cstdint>
#include <array>
#include <optional>
#include <vector>

#include "collide/aabb.h"
#include "collide/disc_walls.h"
#include "collide/obb.h"
#include "collide/ray.h"
#include "collide/sphere.h"
#include "collide/triangle.h"
#include "harness/model/answer.h"
#include "harness/model/mesh_query.h"

namespace cc::cgal {

/// A number held by two adjacent doubles: down, the largest double <= it, and up, the smallest
/// double >= it (equal when it is a double; -inf or +inf beyond the doubles' range).
struct Bracket {
  double down = 0, up = 0;
};

/// CGAL's answer to whether two shapes meet.
struct CgalAnswer {
  bool hit = false;
  /// Where CGAL computes the decision's quantity itself, its sign: > 0 overlapping, 0 touching,
  /// < 0 apart (two spheres: (r_a + r_b)^2 - |c_a - c_b|^2; two k-DOPs: the smallest overlap of
  /// a slab).
  std::optional<int> margin_sign;
  /// Two k-DOPs: the sign of each slab's overlap min(a_hi, b_hi) - max(a_lo, b_lo), in the order
  /// of kdop_directions(k) (> 0 overlapping, 0 touching, < 0 apart).
  std::vector<int> slab_signs;
  /// A ray against a mesh: the faces the ray meets, ascending; a disc against walls: the walls
  /// it touches, ascending.
  std::optional<std::vector<std::uint32_t>> faces;
  /// Two meshes: the pairs of faces (face of a, face of b) that meet, ascending.
  std::optional<std::vector<harness::FacePair>> pairs;
  /// A ray against a mesh, a hit: the first parameter t at which the ray meets the mesh (exact in FT, then
  /// bracketed).
  std::optional<Bracket> first_t;
  /// Two triangles that meet: the corners of their intersection as CGAL constructs it (a point,
  /// a segment's ends, a polygon's corners), each coordinate bracketed by the doubles around it.
  std::vector<std::array<Bracket, 3>> corners;
  /// The distance kinds: the signed distance rounded down (two triangles: the largest double whose
  /// square is at most CGAL's squared distance, 0 where they meet).
  std::optional<double> distance_down;
};

/// Squared distance of the centres against the squared sum of the radii; the signed distance
/// |c_b - c_a| - r_a - r_b rounded down.
CgalAnswer cgal_answer(const Sphere& a, const Sphere& b);
/// A ball against the parallelepiped the box's axes span: the centre's squared distance to the
/// box (CGAL's squared_distance to the pieces of the box, as below: 0 in it) and, for a centre in
/// the box, to its boundary (the least over the planes of its six faces, each through three
/// corners; 0 for a flat box); the signed distance (minus the depth inside) less the radius,
/// rounded down.
CgalAnswer cgal_answer(const Sphere& ball, const Obb& box);
/// Iso_cuboid_3 against Iso_cuboid_3.
CgalAnswer cgal_answer(const Aabb& a, const Aabb& b);
/// The points origin + t dir, tmin <= t <= tmax (a Segment_3, a Ray_3, a line as two Ray_3 from
/// the origin, or a Point_3 when dir is 0 or tmin = tmax; nothing when tmin > tmax) against an
/// Iso_cuboid_3. A direction
/// component whose reciprocal overflows is 0, as the library's contract defines it.
CgalAnswer cgal_answer(const Ray& ray, const Aabb& box);
/// Triangle_3 (Segment_3, Point_3) against Iso_cuboid_3.
CgalAnswer cgal_answer(const Triangle& tri, const Aabb& box);
/// Triangle_3 (Segment_3, Point_3) against the parallelepiped the box's axes span, as the union
/// of the six tetrahedra of its Kuhn triangulation (two triangles, a segment or a point when half
/// extents are 0), and their signed distance: apart, the least squared_distance between the
/// triangle and the triangles of the box's faces; meeting, minus the penetration depth, as for
/// two boxes below.
CgalAnswer cgal_answer(const Triangle& tri, const Obb& box);
/// Triangle_3 (Segment_3, Point_3) against Triangle_3 (Segment_3, Point_3), and their squared
/// distance (CGAL's squared_distance; for a segment and a triangle, which CGAL lacks, 0 where
/// they meet, else the least of its ends against the triangle and it against the edges); when they meet,
/// the corners of CGAL::intersection.
CgalAnswer cgal_answer(const Triangle& a, const Triangle& b);
/// The two parallelepipeds, each as above, and their signed distance: apart, the least
/// squared_distance between the triangles of their faces (the pieces of a flat box); meeting,
/// minus the penetration depth: the least squared distance from the origin to the planes of the
/// faces of CGAL's convex hull (convex_hull_3) of their Minkowski difference, 0 where it is flat.
CgalAnswer cgal_answer(const Obb& a, const Obb& b);
/// The exact k-DOPs of the two point sets: for each direction n of kdop_directions(k), the
/// smallest and largest n . p of each set (in FT) and the sign of the slabs' overlap; a hit iff
/// no slab is apart, margin_sign the smallest slab sign. An empty set's k-DOP is empty: every
/// slab apart. k must have a direction set.
CgalAnswer cgal_answer(int k, const std::vector<Vec3>& a, const std::vector<Vec3>& b);
/// The ray's points (the parts above, but a subnormal direction component stays as it is)
/// against every face of the mesh (Triangle_3, or Segment_3 or Point_3 as a triangle above): the
/// faces it meets and, for a hit, the smallest t over the points where it meets them, t = (P -
/// origin) . dir / (dir . dir), a segment of points counting by its ends; with a zero direction
/// the origin alone, t = tmin (which may be -inf). The mesh must be valid (mesh_problem). The
/// hierarchy the library is asked to use does not change the answer.
CgalAnswer cgal_answer(const Ray& ray, const harness::MeshRef& mesh, const harness::LibraryBvh& library);
/// Two meshes, each vertex placed exactly by its pose (rotation p + translation in FT), each face
/// its pieces as a triangle above: the pairs of faces that meet, tried where their boxes (the
/// intervals CGAL holds the placed vertices in) meet; a hit iff any does; their distance, 0 where
/// they meet, else the least squared_distance over all pairs of faces, taken in the order of a
/// lower bound (their boxes' gap, rounded down) and stopped where it exceeds the least found;
/// rounded down. The meshes must be valid (mesh_problem). The hierarchy the library is asked to
/// use does not change the answer.
CgalAnswer cgal_answer(const harness::MeshPair& meshes);
/// The disc against each wall in the plane: the squared distance from its centre (Point_2) to
/// the wall (Segment_2, or Point_2 when its ends are equal) against the squared radius; the walls
/// touched in `faces`. A wall with a NaN or infinite end is never touched (the kind's contract).
/// The disc must be finite with a radius >= 0.
CgalAnswer cgal_answer(const Disc& disc, const std::vector<Wall>& walls);

}  // namespace cc::cgal
