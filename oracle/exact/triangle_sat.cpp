#include "oracle/exact/triangle_sat.h"

#include <cmath>
#include <limits>

#include "oracle/exact/convex_sat.h"
#include "oracle/exact/dyadic.h"
#include "oracle/exact/rational.h"

namespace cc::exact {
namespace {

// d = m 2^e with m an integer of at most 53 bits (d finite and nonzero).
void split(double d, long& m, long& e) {
  int k = 0;
  const double f = std::frexp(d, &k);
  m = static_cast<long>(std::ldexp(f, 53));
  e = k - 53;
}

}  // namespace

DyadicPoint placed_dyadic(const RigidTransform& pose, const Vec3& v) {
  // Coordinate i is the sum of R_ij v_j (j = 0, 1, 2) and t_i: each term m 2^e.
  long m[3][4][2] = {}, e[3][4] = {};
  bool present[3][4] = {};
  long least = std::numeric_limits<long>::max();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double x = j < 3 ? pose.rotation(i, j) : pose.translation[i];
      const double y = j < 3 ? v[j] : 1.0;
      if (x == 0 || y == 0) continue;
      long ex = 0, ey = 0;
      split(x, m[i][j][0], ex);
      split(y, m[i][j][1], ey);
      e[i][j] = ex + ey;
      present[i][j] = true;
      least = std::min(least, e[i][j]);
    }
  }
  DyadicPoint p;
  if (least == std::numeric_limits<long>::max()) return p;  // the origin
  p.exponent = least;
  mpz_class term;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      if (!present[i][j]) continue;
      mpz_set_si(term.get_mpz_t(), m[i][j][0]);
      mpz_mul_si(term.get_mpz_t(), term.get_mpz_t(), m[i][j][1]);
      mpz_mul_2exp(term.get_mpz_t(), term.get_mpz_t(), static_cast<unsigned long>(e[i][j] - least));
      p.c[i] += term;
    }
  }
  // Common factors of two go into the exponent, so that the integers stay short.
  std::size_t zeros = std::numeric_limits<std::size_t>::max();
  for (const mpz_class& c : p.c) {
    if (sgn(c) != 0) zeros = std::min<std::size_t>(zeros, mpz_scan1(c.get_mpz_t(), 0));
  }
  if (zeros == std::numeric_limits<std::size_t>::max()) return DyadicPoint{};
  for (mpz_class& c : p.c) mpz_tdiv_q_2exp(c.get_mpz_t(), c.get_mpz_t(), zeros);
  p.exponent += static_cast<long>(zeros);
  return p;
}

namespace {

// The index among the 20 of each triple i < j < k of the six edges (-1 elsewhere).
struct TripleIndex {
  std::array<std::array<std::array<int, 6>, 6>, 6> of{};
  constexpr TripleIndex() {
    int index = 0;
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        for (int k = 0; k < 6; ++k) of[i][j][k] = -1;
      }
    }
    for (int i = 0; i < 6; ++i) {
      for (int j = i + 1; j < 6; ++j) {
        for (int k = j + 1; k < 6; ++k) of[i][j][k] = index++;
      }
    }
  }
};
constexpr TripleIndex kTriple;

int triple_index(int i, int j, int k) { return kTriple.of[i][j][k]; }

}  // namespace

// [e_i, e_j, e_k] into out (0 when two indices are equal or an edge is zero).
void TriangleSat::triple(mpz_class& out, int i, int j, int k) {
  if (i == j || j == k || i == k) {
    out = 0;
    return;
  }
  bool odd = false;  // the permutation that sorts (i, j, k)
  if (i > j) std::swap(i, j), odd = !odd;
  if (j > k) std::swap(j, k), odd = !odd;
  if (i > j) std::swap(i, j), odd = !odd;
  out = triples_[triple_index(i, j, k)];
  if (odd) mpz_neg(out.get_mpz_t(), out.get_mpz_t());
}

void TriangleSat::gap_from(const mpz_class& t0, const mpz_class& t2, const mpz_class& t3, const mpz_class& t5,
                           const mpz_class& w) {
  // a's vertices relative to a0 project to 0, t0, -t2; b's to w, w + t3, w - t5.
  const auto extremes = [&](const mpz_class& x, const mpz_class& y, mpz_class& lo, mpz_class& hi) {
    mpz_neg(other_.get_mpz_t(), y.get_mpz_t());
    lo = 0, hi = 0;
    for (const mpz_class* v : {&x, static_cast<const mpz_class*>(&other_)}) {
      if (*v < lo) lo = *v;
      if (*v > hi) hi = *v;
    }
  };
  extremes(t0, t2, lo_a_, hi_a_);
  extremes(t3, t5, lo_b_, hi_b_);
  lo_b_ += w, hi_b_ += w;
  mpz_sub(gap_.get_mpz_t(), lo_b_.get_mpz_t(), hi_a_.get_mpz_t());
  mpz_sub(other_.get_mpz_t(), lo_a_.get_mpz_t(), hi_b_.get_mpz_t());
  if (other_ > gap_) mpz_swap(other_.get_mpz_t(), gap_.get_mpz_t());
}

// exact_sat's steps (convex_sat.cpp), on integers: with the points on 2^E, edges are on 2^E,
// their cross products on 2^2E, projections onto those on 2^3E; for coplanar directions the
// plane normal n is on 2^2E, the in-plane normals n x d on 2^3E, projections onto them on 2^4E.
// A projection is taken relative to a's first vertex: along a cross product of edges e_i x e_j,
// the other vertices' offsets project to triple products [e_i, e_j, e_k] of the six edges (20 of
// them, each computed once), and b's first vertex to one product with w = b0 - a0.
std::optional<TriangleSatVerdict> TriangleSat::operator()(const std::array<const DyadicPoint*, 3>& a,
                                                          const std::array<const DyadicPoint*, 3>& b) {
  const std::array<const DyadicPoint*, 6> all{a[0], a[1], a[2], b[0], b[1], b[2]};
  long least = std::numeric_limits<long>::max();
  for (const DyadicPoint* p : all) least = std::min(least, p->exponent);
  for (int k = 0; k < 6; ++k) {
    for (int i = 0; i < 3; ++i) {
      mpz_mul_2exp(points_[k][i].get_mpz_t(), all[k]->c[i].get_mpz_t(),
                   static_cast<unsigned long>(all[k]->exponent - least));
    }
  }
  for (int i = 0; i < 3; ++i) mpz_sub(w_[i].get_mpz_t(), points_[3][i].get_mpz_t(), points_[0][i].get_mpz_t());
  // The edges v[i + 1] - v[i] of a (0, 1, 2), then of b (3, 4, 5); the directions are the
  // nonzero ones, in that order.
  int n = 0;
  std::array<int, 6> direction;  // edge of each direction
  std::array<bool, 6> zero{};
  std::array<Magnitude, 6> lengths;  // per direction
  for (int e = 0; e < 6; ++e) {
    const int t = e / 3, i = e % 3;
    for (int k = 0; k < 3; ++k) {
      mpz_sub(edges_[e][k].get_mpz_t(), points_[3 * t + (i + 1) % 3][k].get_mpz_t(), points_[3 * t + i][k].get_mpz_t());
    }
    zero[e] = sgn(edges_[e][0]) == 0 && sgn(edges_[e][1]) == 0 && sgn(edges_[e][2]) == 0;
    if (zero[e]) continue;
    dot(squares_[n], edges_[e], edges_[e]);
    lengths[n] = length_from_square(squares_[n], least);
    direction[n++] = e;
  }
  // Cross products of every pair of directions, and triple products of every three; rank 3 when
  // one of those is nonzero.
  int pairs = 0;
  std::array<std::pair<int, int>, 15> pair_of;  // directions
  bool flat = false, spans = false;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      Vec& c = crosses_[pairs];
      cross(c, edges_[direction[i]], edges_[direction[j]]);
      pair_of[pairs++] = {i, j};
      const bool nonzero = sgn(c[0]) != 0 || sgn(c[1]) != 0 || sgn(c[2]) != 0;
      flat |= nonzero;
      for (int k = j + 1; k < n; ++k) {
        mpz_class& t = triples_[triple_index(direction[i], direction[j], direction[k])];
        if (nonzero) {
          dot(t, c, edges_[direction[k]]);
        } else {
          t = 0;
        }
        spans |= sgn(t) != 0;
      }
    }
  }
  if (!flat) return std::nullopt;  // rank 1 or 0
  for (int e = 0; e < 6; ++e) {  // triples with a zero edge
    if (!zero[e]) continue;
    for (int i = 0; i < 6; ++i) {
      for (int j = i + 1; j < 6; ++j) {
        if (i != e && j != e) {
          int x = i, y = j, z = e;
          if (z < y) std::swap(y, z);
          if (y < x) std::swap(x, y);
          triples_[triple_index(x, y, z)] = 0;
        }
      }
    }
  }
  TriangleSatVerdict verdict;
  verdict.rank = spans ? 3 : 2;

  double best_separation = -std::numeric_limits<double>::infinity();
  double worst_overlap = std::numeric_limits<double>::infinity();
  bool separated = false;
  // The gap (in gap_, on 2^(axis_exponent + E)) along an axis: separating or overlapping.
  const auto consider = [&](const Vec& axis, long axis_exponent, const Magnitude& conditioning) {
    const Magnitude g = nearest_magnitude(gap_, axis_exponent + least);
    if (sgn(gap_) > 0) {
      separated = true;
      best_separation = std::max(best_separation, separation_along(g, conditioning));
    } else if (verdict.rank == 3 && !separated) {  // the overlap counts only when nothing separates
      dot(product_, axis, axis);
      worst_overlap = std::min(worst_overlap, overlap_along(g, length_from_square(product_, axis_exponent)));
    }
  };
  // Along e_i x e_j: the triple products with the edges a0->a1, a2->a0, b0->b1, b2->b0.
  const auto along_cross = [&](int p) {
    const int i = direction[pair_of[p].first], j = direction[pair_of[p].second];
    triple(t_[0], i, j, 0);
    triple(t_[1], i, j, 2);
    triple(t_[2], i, j, 3);
    triple(t_[3], i, j, 5);
    dot(product_, crosses_[p], w_);
    gap_from(t_[0], t_[1], t_[2], t_[3], product_);
  };
  if (verdict.rank == 3) {
    for (int p = 0; p < pairs; ++p) {
      const Vec& c = crosses_[p];
      if (sgn(c[0]) == 0 && sgn(c[1]) == 0 && sgn(c[2]) == 0) continue;
      along_cross(p);
      consider(c, 2 * least, lengths[pair_of[p].first] * lengths[pair_of[p].second]);
    }
  } else {
    // The plane normal from the best-conditioned pair: the largest |di x dj|^2 / (|di|^2 |dj|^2),
    // the first on ties, compared by cross-multiplying.
    int best = 0;
    for (int p = 1; p < pairs; ++p) {
      const auto [i, j] = pair_of[p];
      const auto [bi, bj] = pair_of[best];
      dot(product_, crosses_[p], crosses_[p]);
      product_ *= squares_[bi];
      product_ *= squares_[bj];
      dot(other_, crosses_[best], crosses_[best]);
      other_ *= squares_[i];
      other_ *= squares_[j];
      if (product_ > other_) best = p;
    }
    const Magnitude normal_conditioning = lengths[pair_of[best].first] * lengths[pair_of[best].second];
    along_cross(best);
    consider(crosses_[best], 2 * least, normal_conditioning);
    for (int k = 0; k < n; ++k) {
      cross(axis_, crosses_[best], edges_[direction[k]]);
      dot(t_[0], axis_, edges_[0]);
      dot(t_[1], axis_, edges_[2]);
      dot(t_[2], axis_, edges_[3]);
      dot(t_[3], axis_, edges_[5]);
      dot(product_, axis_, w_);
      gap_from(t_[0], t_[1], t_[2], t_[3], product_);
      consider(axis_, 3 * least, normal_conditioning * lengths[k]);
    }
  }
  verdict.hit = !separated;
  verdict.margin = verdict.hit ? (verdict.rank == 3 ? worst_overlap : 0) : -best_separation;
  return verdict;
}

}  // namespace cc::exact

namespace cc::exact {

DyadicPoint dyadic(const Vec3& v) { return placed_dyadic(RigidTransform{Mat3::identity(), {0, 0, 0}}, v); }

TriangleSatVerdict triangle_pair_sat(const Triangle& a, const Triangle& b) {
  thread_local TriangleSat sat;
  const std::array<DyadicPoint, 6> p = {dyadic(a.v[0]), dyadic(a.v[1]), dyadic(a.v[2]),
                                        dyadic(b.v[0]), dyadic(b.v[1]), dyadic(b.v[2])};
  if (const std::optional<TriangleSatVerdict> r = sat({&p[0], &p[1], &p[2]}, {&p[3], &p[4], &p[5]})) return *r;
  const SatResult q = exact_sat(triangle_shape(a.v[0], a.v[1], a.v[2], "A"), triangle_shape(b.v[0], b.v[1], b.v[2], "B"));
  return {q.hit, q.rank, q.margin};
}

}  // namespace cc::exact
