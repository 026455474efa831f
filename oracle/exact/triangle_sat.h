// exact_sat for two triangles whose vertices are dyadic rationals (doubles placed by a pose), in
// integer arithmetic: every coordinate of the pair on one power of two, so sums and products
// are GMP integer operations on reused storage, with no gcd and no allocation once warm.
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>

#include "collide/rigid_transform.h"
#include "collide/triangle.h"

namespace cc::exact {

/// A point (x, y, z) 2^exponent with integer x, y, z: every dyadic rational point is one.
struct DyadicPoint {
  std::array<mpz_class, 3> c;
  long exponent = 0;
};

/// R v + t, exactly (pose and vertex finite).
DyadicPoint placed_dyadic(const RigidTransform& pose, const Vec3& v);
/// v itself (finite).
DyadicPoint dyadic(const Vec3& v);

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
class TriangleSat;

/// exact_sat(triangle_shape(a...), triangle_shape(b...)) for two triangles of finite doubles:
/// in integer arithmetic by a TriangleSat of this thread where it takes them, else in rationals;
/// the same hit, rank and margin either way.
TriangleSatVerdict triangle_pair_sat(const Triangle& a, const Triangle& b);

class TriangleSat {
 public:
  std::optional<TriangleSatVerdict> operator()(const std::array<const DyadicPoint*, 3>& a,
                                               const std::array<const DyadicPoint*, 3>& b);

 private:
  using Vec = std::array<mpz_class, 3>;
  // out = [e_i, e_j, e_k], the triple product of three edges, from triples_.
  void triple(mpz_class& out, int i, int j, int k);
  // gap_ = max(b.lo - a.hi, a.lo - b.hi) along an axis, from the projections of the edges
  // a0->a1 (t0), a2->a0 (t2), b0->b1 (t3), b2->b0 (t5) and of w = b0 - a0.
  void gap_from(const mpz_class& t0, const mpz_class& t2, const mpz_class& t3, const mpz_class& t5,
                const mpz_class& w);

  std::array<Vec, 6> points_;    // a's vertices, then b's, on one power of two
  std::array<Vec, 6> edges_;     // a's edges v[i + 1] - v[i], then b's
  std::array<Vec, 15> crosses_;  // of every pair of nonzero edges
  std::array<mpz_class, 20> triples_;  // [e_i, e_j, e_k], i < j < k
  std::array<mpz_class, 6> squares_;
  std::array<mpz_class, 4> t_;
  Vec w_, axis_;
  mpz_class product_, lo_a_, hi_a_, lo_b_, hi_b_, gap_, other_;
};

}  // namespace cc::exact
