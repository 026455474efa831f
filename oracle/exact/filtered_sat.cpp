#include "oracle/exact/filtered_sat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "oracle/exact/bounded.h"
#include "oracle/exact/dyadic.h"

namespace cc::exact {
namespace {

thread_local SatFilterCounts t_counts;

// A shape as exact_shape builds it, in floating point: the same directions in the same order.
struct FloatShape {
  std::vector<BoundedVec3> vertices;    // triangles
  BoundedVec3 center;                   // parallelepipeds
  std::vector<BoundedVec3> half_edges;  // parallelepipeds
  std::vector<BoundedVec3> directions;

  struct Projection {
    Bounded lo, hi;
  };
  Projection project(const BoundedVec3& axis) const {
    if (!vertices.empty()) {
      Projection r{dot(axis, vertices[0]), dot(axis, vertices[0])};
      for (std::size_t i = 1; i < vertices.size(); ++i) {
        const Bounded p = dot(axis, vertices[i]);
        r.lo = min(r.lo, p), r.hi = max(r.hi, p);
      }
      return r;
    }
    const Bounded mid = dot(axis, center);
    Bounded radius;
    for (const BoundedVec3& h : half_edges) radius = radius + abs(dot(axis, h));
    return {mid - radius, mid + radius};
  }
};

bool is_zero(const Vec3& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

// The same skips as triangle_shape, parallelepiped_shape and box_shape (convex_sat.cpp): an
// edge between equal vertices, a column with a zero half extent or no length, an axis on which
// lo == hi.
FloatShape float_shape(const SatInput& input) {
  FloatShape s;
  if (const auto* t = std::get_if<Triangle>(&input)) {
    for (const Vec3& v : t->v) s.vertices.push_back(exactly(v));
    for (int i = 0; i < 3; ++i) {
      const Vec3& from = t->v[i];
      const Vec3& to = t->v[(i + 1) % 3];
      if (from == to) continue;
      s.directions.push_back(exactly(to) - exactly(from));
    }
  } else if (const auto* b = std::get_if<Obb>(&input)) {
    s.center = exactly(b->center);
    for (int i = 0; i < 3; ++i) {
      const Vec3& column = b->axes.col[i];
      if (b->half[i] == 0 || is_zero(column)) continue;
      s.half_edges.push_back(exactly(b->half[i]) * exactly(column));
      s.directions.push_back(exactly(column));
    }
  } else {
    const Aabb& box = std::get<Aabb>(input);
    s.center = exactly(0.5) * (exactly(box.lo) + exactly(box.hi));
    for (int i = 0; i < 3; ++i) {
      if (box.lo[i] == box.hi[i]) continue;
      BoundedVec3 half{}, axis{};
      const Bounded extent = exactly(0.5) * (exactly(box.hi[i]) - exactly(box.lo[i]));
      (i == 0 ? half.x : i == 1 ? half.y : half.z) = extent;
      (i == 0 ? axis.x : i == 1 ? axis.y : axis.z) = exactly(1);
      s.half_edges.push_back(half);
      s.directions.push_back(axis);
    }
  }
  return s;
}

// Some triple product of the directions is certainly nonzero: they span space (rank 3).
bool spans_space(const std::vector<BoundedVec3>& d) {
  for (std::size_t i = 0; i < d.size(); ++i) {
    for (std::size_t j = i + 1; j < d.size(); ++j) {
      const BoundedVec3 c = cross(d[i], d[j]);
      for (std::size_t k = 0; k < d.size(); ++k) {
        if (dot(c, d[k]).certain()) return true;
      }
    }
  }
  return false;
}

// An interval that holds what an axis counts for in the margin (separation_along or
// overlap_along of its exact gap): the quotient of the gap's interval by the divisor's, widened
// by 2^-38 for the roundings of the exact path and of this one, and by 2^-1000 for underflow.
struct Estimate {
  double lo = 0, hi = INFINITY;
};
Estimate quotient(double gap_lo, double gap_hi, double divisor_lo, double divisor_hi) {
  constexpr double kRelative = 0x1p-38, kAbsolute = 0x1p-1000;
  Estimate r;
  r.lo = gap_lo / divisor_hi * (1 - kRelative) - kAbsolute;
  r.hi = divisor_lo > 0 ? gap_hi / divisor_lo * (1 + kRelative) + kAbsolute : INFINITY;
  return r;
}

// One candidate axis: the cross product of directions i and j.
struct Candidate {
  std::size_t i = 0, j = 0;
  bool placed = false;   // by floating point: a nonzero axis and a gap of certain sign
  bool present = true;   // false: the exact cross product vanishes, not an axis
  bool separates = false;
  Estimate value;                  // of separation_along or overlap_along
  std::optional<double> exact;     // the value itself, where taken exactly
};

// The exact side, built when first needed, on integers: every double of both inputs on one
// power of two 2^L, L below 0 and below the last bit of each of them, so that 1 and a box's
// halves (lo + hi) / 2 and (hi - lo) / 2 are integers too. Vertices, centres and directions are
// then on 2^L, half edges and cross products on 2^2L, and projections are taken on 2^4L (one
// onto a vertex or a centre, on 2^3L, shifted by -L bits). The same shapes as exact_shape, the
// same gaps, and the same roundings of the margins (dyadic.h), without a gcd.
class ExactSide {
 public:
  ExactSide(const SatInput& a, const SatInput& b) {
    long lowest = 0;
    for (const SatInput* s : {&a, &b}) {
      if (const auto* t = std::get_if<Triangle>(s)) {
        for (const Vec3& v : t->v) lowest = lowest_exponent(v, lowest);
      } else if (const auto* o = std::get_if<Obb>(s)) {
        for (const Vec3* v : {&o->center, &o->half, &o->axes.col[0], &o->axes.col[1], &o->axes.col[2]}) {
          lowest = lowest_exponent(*v, lowest);
        }
      } else {
        const Aabb& box = std::get<Aabb>(*s);
        lowest = lowest_exponent(box.hi, lowest_exponent(box.lo, lowest));
      }
    }
    exponent_ = lowest - 1;
    unit_shift_ = static_cast<unsigned long>(-exponent_);
    shapes_[0] = shape(a);
    shapes_[1] = shape(b);
    for (const Shape& s : shapes_) dirs_.insert(dirs_.end(), s.directions.begin(), s.directions.end());
    lengths_.resize(dirs_.size());
  }
  std::size_t direction_count() const { return dirs_.size(); }

  // The candidate's axis exactly: whether it exists, whether it separates, and its value.
  void settle(Candidate& c) {
    ++t_counts.exact_axes;
    cross(axis_, dirs_[c.i], dirs_[c.j]);
    c.present = !exact::is_zero(axis_);
    if (!c.present) return;
    project(shapes_[0], lo_a_, hi_a_);
    project(shapes_[1], lo_b_, hi_b_);
    mpz_sub(gap_.get_mpz_t(), lo_b_.get_mpz_t(), hi_a_.get_mpz_t());
    mpz_sub(other_.get_mpz_t(), lo_a_.get_mpz_t(), hi_b_.get_mpz_t());
    if (other_ > gap_) mpz_swap(other_.get_mpz_t(), gap_.get_mpz_t());
    c.separates = sgn(gap_) > 0;
    const Magnitude gap = nearest_magnitude(gap_, 4 * exponent_);
    if (c.separates) {
      c.exact = separation_along(gap, length_of(c.i) * length_of(c.j));
    } else {
      dot(product_, axis_, axis_);
      c.exact = overlap_along(gap, length_from_square(product_, 2 * exponent_));
    }
  }

 private:
  using Vec = IntVec3;
  struct Shape {
    std::vector<Vec> vertices;    // triangles, on 2^L
    Vec center;                   // parallelepipeds, on 2^L
    std::vector<Vec> half_edges;  // parallelepipeds, on 2^2L
    std::vector<Vec> directions;  // on 2^L
  };

  // The skips of float_shape and exact_shape.
  Shape shape(const SatInput& input) const {
    Shape s;
    if (const auto* t = std::get_if<Triangle>(&input)) {
      for (const Vec3& v : t->v) s.vertices.push_back(on_grid(v, exponent_));
      for (int i = 0; i < 3; ++i) {
        if (t->v[i] == t->v[(i + 1) % 3]) continue;
        Vec e;
        for (int k = 0; k < 3; ++k) mpz_sub(e[k].get_mpz_t(), s.vertices[(i + 1) % 3][k].get_mpz_t(), s.vertices[i][k].get_mpz_t());
        s.directions.push_back(std::move(e));
      }
    } else if (const auto* b = std::get_if<Obb>(&input)) {
      s.center = on_grid(b->center, exponent_);
      for (int i = 0; i < 3; ++i) {
        const Vec3& column = b->axes.col[i];
        if (b->half[i] == 0 || (column.x == 0 && column.y == 0 && column.z == 0)) continue;
        Vec k = on_grid(column, exponent_), h;
        mpz_class half;
        set_on(half, b->half[i], exponent_);
        for (int j = 0; j < 3; ++j) mpz_mul(h[j].get_mpz_t(), half.get_mpz_t(), k[j].get_mpz_t());
        s.half_edges.push_back(std::move(h));
        s.directions.push_back(std::move(k));
      }
    } else {
      const Aabb& box = std::get<Aabb>(input);
      const Vec lo = on_grid(box.lo, exponent_), hi = on_grid(box.hi, exponent_);  // even integers: L is below their last bits
      for (int k = 0; k < 3; ++k) {
        mpz_add(s.center[k].get_mpz_t(), lo[k].get_mpz_t(), hi[k].get_mpz_t());
        mpz_tdiv_q_2exp(s.center[k].get_mpz_t(), s.center[k].get_mpz_t(), 1);
      }
      for (int i = 0; i < 3; ++i) {
        if (box.lo[i] == box.hi[i]) continue;
        Vec h{0, 0, 0}, axis{0, 0, 0};
        mpz_sub(h[i].get_mpz_t(), hi[i].get_mpz_t(), lo[i].get_mpz_t());
        mpz_mul_2exp(h[i].get_mpz_t(), h[i].get_mpz_t(), unit_shift_ - 1);  // (hi - lo) / 2 times 2^-L
        mpz_set_ui(axis[i].get_mpz_t(), 1);
        mpz_mul_2exp(axis[i].get_mpz_t(), axis[i].get_mpz_t(), unit_shift_);  // 1 on 2^L
        s.half_edges.push_back(std::move(h));
        s.directions.push_back(std::move(axis));
      }
    }
    return s;
  }

  // The shape's extent along axis_, on 2^4L.
  void project(const Shape& s, mpz_class& lo, mpz_class& hi) {
    if (!s.vertices.empty()) {
      for (std::size_t i = 0; i < s.vertices.size(); ++i) {
        dot(product_, axis_, s.vertices[i]);
        if (i == 0 || product_ < lo) lo = product_;
        if (i == 0 || product_ > hi) hi = product_;
      }
      mpz_mul_2exp(lo.get_mpz_t(), lo.get_mpz_t(), unit_shift_);
      mpz_mul_2exp(hi.get_mpz_t(), hi.get_mpz_t(), unit_shift_);
      return;
    }
    dot(product_, axis_, s.center);
    mpz_mul_2exp(product_.get_mpz_t(), product_.get_mpz_t(), unit_shift_);
    radius_ = 0;
    for (const Vec& h : s.half_edges) {
      dot(other_, axis_, h);
      mpz_abs(other_.get_mpz_t(), other_.get_mpz_t());
      radius_ += other_;
    }
    mpz_sub(lo.get_mpz_t(), product_.get_mpz_t(), radius_.get_mpz_t());
    mpz_add(hi.get_mpz_t(), product_.get_mpz_t(), radius_.get_mpz_t());
  }

  // The length of direction i, computed when first asked (an intersecting pair needs none).
  Magnitude length_of(std::size_t i) {
    if (!lengths_[i]) {
      dot(product_, dirs_[i], dirs_[i]);
      lengths_[i] = length_from_square(product_, exponent_);
    }
    return *lengths_[i];
  }

  long exponent_ = 0;             // L
  unsigned long unit_shift_ = 0;  // -L: 1 on 2^L is 2^-L
  std::array<Shape, 2> shapes_;
  std::vector<Vec> dirs_;
  std::vector<std::optional<Magnitude>> lengths_;
  Vec axis_;
  mpz_class lo_a_, hi_a_, lo_b_, hi_b_, gap_, other_, product_, radius_;
};

std::optional<TriangleSatVerdict> filtered(const SatInput& a, const SatInput& b) {
  const FloatShape fa = float_shape(a), fb = float_shape(b);
  std::vector<BoundedVec3> dirs = fa.directions;
  dirs.insert(dirs.end(), fb.directions.begin(), fb.directions.end());
  if (!spans_space(dirs)) return std::nullopt;
  std::vector<LengthBounds> lengths;
  for (const BoundedVec3& d : dirs) {
    lengths.push_back(length_bounds(d));
    if (!(lengths.back().lo > 0) || !std::isfinite(lengths.back().hi)) return std::nullopt;
  }

  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    for (std::size_t j = i + 1; j < dirs.size(); ++j) {
      Candidate c;
      c.i = i, c.j = j;
      const BoundedVec3 axis = cross(dirs[i], dirs[j]);
      if (!axis.x.finite() || !axis.y.finite() || !axis.z.finite()) return std::nullopt;
      if (axis.x.zero() && axis.y.zero() && axis.z.zero()) {
        c.placed = true, c.present = false;
      } else if (axis.x.certain() || axis.y.certain() || axis.z.certain()) {
        const FloatShape::Projection pa = fa.project(axis), pb = fb.project(axis);
        const Bounded gap = max(pb.lo - pa.hi, pa.lo - pb.hi);
        if (!gap.finite()) return std::nullopt;
        if (gap.zero()) {
          c.placed = true;
          c.exact = 0.0;  // overlap_along of a zero gap: touching
        } else if (gap.certain()) {
          c.placed = true;
          c.separates = gap.v > 0;
          const double size = std::fabs(gap.v);
          if (c.separates) {
            c.value = quotient(size - gap.e, size + gap.e, lengths[i].lo * lengths[j].lo, lengths[i].hi * lengths[j].hi);
          } else {
            const LengthBounds n = length_bounds(axis);
            c.value = quotient(size - gap.e, size + gap.e, n.lo, n.hi);
          }
        }
      }
      candidates.push_back(c);
    }
  }

  std::optional<ExactSide> exact;
  const auto settle = [&](Candidate& c) {
    if (!exact) {
      exact.emplace(a, b);
      if (exact->direction_count() != dirs.size()) return false;
    }
    exact->settle(c);
    return true;
  };
  for (Candidate& c : candidates) {
    if (!c.placed && !settle(c)) return std::nullopt;
  }
  bool hit = true;
  for (const Candidate& c : candidates) hit = hit && !(c.present && c.separates);

  // The extreme value over the candidates that count (the separating ones when apart, all when
  // intersecting): the largest separation or the smallest overlap. Only a candidate whose
  // interval reaches past the best bound of the others can be it; those are taken exactly, in
  // exact_sat's order, with its comparisons (the first extreme one wins).
  const bool apart = !hit;
  double bound = apart ? -INFINITY : INFINITY;
  for (const Candidate& c : candidates) {
    if (!c.present || c.separates != apart) continue;
    const double v = c.exact ? *c.exact : (apart ? c.value.lo : c.value.hi);
    bound = apart ? std::max(bound, v) : std::min(bound, v);
  }
  double extreme = apart ? -INFINITY : INFINITY;
  for (Candidate& c : candidates) {
    if (!c.present || c.separates != apart) continue;
    if (!c.exact && (apart ? c.value.hi >= bound : c.value.lo <= bound) && !settle(c)) return std::nullopt;
    if (!c.exact) continue;
    if (apart ? *c.exact > extreme : *c.exact < extreme) extreme = *c.exact;
  }
  TriangleSatVerdict v;
  v.hit = hit;
  v.rank = 3;
  v.margin = apart ? -extreme : extreme;
  return v;
}

}  // namespace

ExactShape exact_shape(const SatInput& s, const std::string& name) {
  if (const auto* t = std::get_if<Triangle>(&s)) return triangle_shape(t->v[0], t->v[1], t->v[2], name);
  if (const auto* b = std::get_if<Obb>(&s)) return parallelepiped_shape(b->center, b->half, b->axes, name);
  const Aabb& box = std::get<Aabb>(s);
  return box_shape(box.lo, box.hi, name);
}

TriangleSatVerdict sat_verdict(const SatInput& a, const SatInput& b) {
  if (const std::optional<TriangleSatVerdict> v = filtered(a, b)) {
    ++t_counts.filtered;
    return *v;
  }
  ++t_counts.whole;
  const SatResult r = exact_sat(exact_shape(a, "A"), exact_shape(b, "B"));
  return {r.hit, r.rank, r.margin};
}

SatFilterCounts sat_filter_counts() { return t_counts; }

}  // namespace cc::exact
