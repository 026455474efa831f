// An exact separating-axis test for two convex polytopes, complete for every degenerate case.
//
// A and B are disjoint iff the origin lies outside their Minkowski difference M = A - B. When M
// is full-dimensional its facet normals are cross products of two edge directions of A and B
// (faces of A, faces of B, an edge of each). When M is flat, lies on a line or is a point, the
// candidates are the plane normal N and the in-plane normals N x g, the line direction g and
// g x (g x o), or o, where o = centre(B) - centre(A) lies in -M. The rank of the edge
// directions tells which case holds, in exact arithmetic.
#pragma once

#include <string>
#include <vector>

#include <optional>
#include <utility>

#include "harness/model/input.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// A convex polytope: a triangle (given by vertices) or a parallelepiped (centre +- half edges).
struct ExactShape {
  QVec3 center;                       // a point of the shape's centre of symmetry or centroid
  std::vector<QVec3> vertices;        // triangles: the 3 vertices
  std::vector<QVec3> half_edges;      // parallelepipeds: the shape is center + sum(+-half_edges)
  std::vector<QVec3> directions;      // nonzero edge directions
  std::vector<std::string> names;     // one per direction, e.g. "A.x" or "B.e1"

  struct Interval {
    Rational lo, hi;
  };
  Interval project(const QVec3& axis) const;
};

/// A triangle with vertices p0, p1, p2; its directions are its nonzero edges p1-p0, p2-p1, p0-p2.
ExactShape triangle_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const std::string& name);
ExactShape rational_triangle_shape(const QVec3& p0, const QVec3& p1, const QVec3& p2, const std::string& name);

/// The parallelepiped centre + sum_i u_i half[i] col_i, |u_i| <= 1; a direction per column with
/// half[i] > 0. An axis-aligned box is the case of the identity.
ExactShape parallelepiped_shape(const Vec3& center, const Vec3& half, const Mat3& columns, const std::string& name);
/// The box [lo, hi] (lo <= hi).
ExactShape box_shape(const Vec3& lo, const Vec3& hi, const std::string& name);

/// One candidate axis and what it shows.
struct AxisReport {
  std::string name;           // e.g. "A.x x B.e1"
  QVec3 axis;
  ExactShape::Interval a, b;  // projections of A and B
  Rational gap;               // max(b.lo - a.hi, a.lo - b.hi): > 0 separates
  Magnitude conditioning;     // divisor that turns a positive gap into a length, see SatResult
  Magnitude length;           // |axis|
};

struct SatResult {
  bool hit = false;
  int rank = 0;  // of the edge directions: 3 full-dimensional, 2 flat, 1 collinear, 0 points
  /// Intersecting: the smallest overlap (-gap / length) over the axes, >= 0: the penetration
  /// depth (0 unless full-dimensional). Disjoint: minus the largest gap / conditioning, < 0: a
  /// distance discounted by how well its axis is determined (for a cross product of two
  /// directions the conditioning is the product of their lengths, so nearly parallel edges
  /// count little; for the axes of collinear and point configurations it is the length).
  double margin = 0;
  int deciding_axis = -1;  // index into axes of the axis that gives the margin
  std::vector<AxisReport> axes;
};

SatResult exact_sat(const ExactShape& a, const ExactShape& b);

/// What a gap > 0 along an axis counts for in SatResult::margin, from the gap rounded
/// (Magnitude::of): gap / conditioning (0 or inf beyond the double range).
double separation_along(Magnitude gap, Magnitude conditioning);
/// What a gap <= 0 along an axis counts for in SatResult::margin, from the gap rounded: the
/// overlap -gap / length, exactly 0 when the shapes touch along it (a zero gap).
double overlap_along(Magnitude gap, Magnitude length);

/// A candidate separating axis and the divisor that turns a gap along it into a length (see
/// SatResult).
struct CandidateAxis {
  std::string name;
  QVec3 axis;
  Magnitude conditioning;
};

/// Candidate axes that decide whether A and B + s are disjoint for every offset s at once (so
/// for shapes moving apart or together): exact_sat's axes when the edge directions span space
/// or a plane; for collinear directions g, the line and two directions across it; for points,
/// the coordinate axes.
std::vector<CandidateAxis> candidate_axes_for_any_offset(const ExactShape& a, const ExactShape& b);

}  // namespace cc::exact
