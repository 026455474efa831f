// exact_sat for two triangles whose vertices are dyadic rationals (doubles placed by a pose), in
// integer arithmetic: every coordinate of the pair on one power of two, so sums and products
// are GMP integer operations on reused storage, with no gcd and no allocation once warm.
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>

#include "collide/rigid_transform.h"

namespace cc::exact {

/// A point (x, y, z) 2^exponent with integer x, y, z: every dyadic rational point is one.
struct DyadicPoint {
  std::array<mpz_class, 3> c;
  long exponent = 0;
};

/// R v + t, exactly (pose and vertex finite).
DyadicPoint placed_dyadic(const RigidTransform& pose, const Vec3& v);

/// What judge_meshes takes of exact_sat's result.
struct TriangleSatVerdict {
  bool hit = false;
  int rank = 0;
  double margin = 0;
};

/// exact_sat(rational_triangle_shape(a...), rational_triangle_shape(b...)) for triangles whose
/// edge directions span space or a plane (rank 3 or 2): the same hit, rank and margin, bit for
/// bit (the margin's roundings are exact_sat's, taken on the integers). Nothing for rank 1 or 0
/// (collinear or coincident vertices in both triangles), whose candidate axes involve the
/// triangles' centroids, thirds that are not dyadic: use exact_sat there. One object per thread;
/// it keeps its integers from pair to pair.
class TriangleSat {
 public:
  std::optional<TriangleSatVerdict> operator()(const std::array<const DyadicPoint*, 3>& a,
                                               const std::array<const DyadicPoint*, 3>& b);

 private:
  using Vec = std::array<mpz_class, 3>;
  void cross(Vec& out, const Vec& u, const Vec& v);
  void dot(mpz_class& out, const Vec& u, const Vec& v);
  // lo, hi: the least and the greatest projection of points_[first, first + 3) on the axis.
  void project(const Vec& axis, int first, mpz_class& lo, mpz_class& hi);

  std::array<Vec, 6> points_;      // a's vertices, then b's, on one power of two
  std::array<Vec, 6> directions_;  // the nonzero edges
  std::array<Vec, 15> crosses_;    // of every pair of directions
  std::array<mpz_class, 6> squares_;
  Vec normal_, axis_;
  mpz_class product_, lo_a_, hi_a_, lo_b_, hi_b_, gap_, other_, scratch_;
};

}  // namespace cc::exact
