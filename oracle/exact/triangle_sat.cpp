#include "oracle/exact/triangle_sat.h"

#include <cmath>
#include <limits>

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

// m 2^e as a Magnitude (as rational.cpp normalises one).
Magnitude normalised(double m, long e) {
  if (m == 0 || !std::isfinite(m)) return {m, 0};
  int k = 0;
  const double f = std::frexp(m, &k);
  return {2 * f, e + k - 1};
}

// The Magnitude of x 2^exponent: x rounded to 53 bits, to nearest, ties to even (as
// Magnitude::of rounds the rational).
Magnitude nearest(const mpz_class& x, long exponent, mpz_class& scratch) {
  const int sign = sgn(x);
  if (sign == 0) return {};
  const std::size_t bits = mpz_sizeinbase(x.get_mpz_t(), 2);
  if (bits <= 53) return normalised(mpz_get_d(x.get_mpz_t()), exponent);
  const std::size_t shift = bits - 53;
  mpz_abs(scratch.get_mpz_t(), x.get_mpz_t());
  const bool half = mpz_tstbit(scratch.get_mpz_t(), shift - 1) != 0;
  const bool beyond_half = mpz_scan1(scratch.get_mpz_t(), 0) < shift - 1;
  mpz_tdiv_q_2exp(scratch.get_mpz_t(), scratch.get_mpz_t(), shift);
  unsigned long q = mpz_get_ui(scratch.get_mpz_t());
  if (half && (beyond_half || (q & 1))) ++q;  // 2^53 at most: exact in a double
  return normalised(sign * static_cast<double>(q), exponent + static_cast<long>(shift));
}

// The Euclidean length of a vector whose squared norm is `square` 2^(2 exponent), as
// exact::length computes it: the square rounded to a double, its square root rounded (an even
// power of two taken out of the square does not change either rounding).
Magnitude length_of(const mpz_class& square, long exponent, mpz_class& scratch) {
  const Magnitude s = nearest(square, 0, scratch);
  if (s.m == 0) return {};
  const bool odd = (s.e % 2) != 0;
  const double root = std::sqrt(odd ? 2 * s.m : s.m);
  return normalised(root, (odd ? s.e - 1 : s.e) / 2 + exponent);
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

void TriangleSat::cross(Vec& out, const Vec& u, const Vec& v) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpz_mul(out[i].get_mpz_t(), u[j].get_mpz_t(), v[k].get_mpz_t());
    mpz_submul(out[i].get_mpz_t(), u[k].get_mpz_t(), v[j].get_mpz_t());
  }
}

void TriangleSat::project(const Vec& axis, int first, mpz_class& lo, mpz_class& hi) {
  dot(lo, axis, points_[first]);
  hi = lo;
  for (int k = first + 1; k < first + 3; ++k) {
    dot(other_, axis, points_[k]);
    if (other_ < lo) {
      lo = other_;
    } else if (other_ > hi) {
      hi = other_;
    }
  }
}

void TriangleSat::dot(mpz_class& out, const Vec& u, const Vec& v) {
  mpz_mul(out.get_mpz_t(), u[0].get_mpz_t(), v[0].get_mpz_t());
  mpz_addmul(out.get_mpz_t(), u[1].get_mpz_t(), v[1].get_mpz_t());
  mpz_addmul(out.get_mpz_t(), u[2].get_mpz_t(), v[2].get_mpz_t());
}

// exact_sat's steps (convex_sat.cpp), on integers: with the points on 2^E, directions are on
// 2^E, their cross products on 2^2E, projections onto those on 2^3E; for coplanar directions the
// plane normal n is on 2^2E, the in-plane normals n x d on 2^3E, projections onto them on 2^4E.
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
  // The nonzero edges v[i + 1] - v[i] of a, then of b, and their lengths.
  int n = 0;
  std::array<Magnitude, 6> lengths;
  for (int t = 0; t < 2; ++t) {
    for (int i = 0; i < 3; ++i) {
      Vec& d = directions_[n];
      for (int k = 0; k < 3; ++k) {
        mpz_sub(d[k].get_mpz_t(), points_[3 * t + (i + 1) % 3][k].get_mpz_t(), points_[3 * t + i][k].get_mpz_t());
      }
      if (sgn(d[0]) == 0 && sgn(d[1]) == 0 && sgn(d[2]) == 0) continue;
      dot(squares_[n], d, d);
      lengths[n] = length_of(squares_[n], least, scratch_);
      ++n;
    }
  }
  // Rank: 3 when some cross product of two directions has a nonzero product with a third.
  int pairs = 0;
  std::array<std::pair<int, int>, 15> pair_of;
  bool spans = false, flat = false;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      Vec& c = crosses_[pairs];
      cross(c, directions_[i], directions_[j]);
      pair_of[pairs++] = {i, j};
      if (sgn(c[0]) == 0 && sgn(c[1]) == 0 && sgn(c[2]) == 0) continue;
      flat = true;
      for (int k = 0; k < n && !spans; ++k) {
        dot(product_, c, directions_[k]);
        spans = sgn(product_) != 0;
      }
    }
  }
  if (!flat) return std::nullopt;  // rank 1 or 0
  TriangleSatVerdict verdict;
  verdict.rank = spans ? 3 : 2;

  // Each candidate's gap max(b.lo - a.hi, a.lo - b.hi).
  const auto gap = [&](const Vec& axis) {
    project(axis, 0, lo_a_, hi_a_);
    project(axis, 3, lo_b_, hi_b_);
    mpz_sub(gap_.get_mpz_t(), lo_b_.get_mpz_t(), hi_a_.get_mpz_t());
    mpz_sub(other_.get_mpz_t(), lo_a_.get_mpz_t(), hi_b_.get_mpz_t());
    if (other_ > gap_) mpz_swap(other_.get_mpz_t(), gap_.get_mpz_t());
  };
  double best_separation = -std::numeric_limits<double>::infinity();
  double worst_overlap = std::numeric_limits<double>::infinity();
  bool separated = false;
  const auto consider = [&](const Vec& axis, long axis_exponent, const Magnitude& conditioning) {
    gap(axis);
    const Magnitude g = nearest(gap_, axis_exponent + least, scratch_);
    if (sgn(gap_) > 0) {
      separated = true;
      best_separation = std::max(best_separation, (g / conditioning).to_double());
    } else if (verdict.rank == 3 && !separated) {  // the overlap counts only when nothing separates
      dot(product_, axis, axis);
      const double overlap = sgn(gap_) == 0 ? 0.0 : -(g / length_of(product_, axis_exponent, scratch_)).to_double();
      worst_overlap = std::min(worst_overlap, overlap);
    }
  };
  if (verdict.rank == 3) {
    for (int p = 0; p < pairs; ++p) {
      const Vec& c = crosses_[p];
      if (sgn(c[0]) == 0 && sgn(c[1]) == 0 && sgn(c[2]) == 0) continue;
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
    normal_ = crosses_[best];
    const Magnitude normal_conditioning = lengths[pair_of[best].first] * lengths[pair_of[best].second];
    consider(normal_, 2 * least, normal_conditioning);
    for (int k = 0; k < n; ++k) {
      cross(axis_, normal_, directions_[k]);
      consider(axis_, 3 * least, normal_conditioning * lengths[k]);
    }
  }
  verdict.hit = !separated;
  verdict.margin = verdict.hit ? (verdict.rank == 3 ? worst_overlap : 0) : -best_separation;
  return verdict;
}

}  // namespace cc::exact
