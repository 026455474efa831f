// The actual rounding of the library's certified quantities, in exact arithmetic: for each
// quantity a probed test recorded (collide/bound_records.h), how far the computation that each
// term of its bound covers was from its exact value, next to the term. The exact value of a
// quantity is that of the recorded doubles it was computed from; where a term covers an error of
// another kind than rounding (axes that are not orthonormal), the error is measured against the
// exact geometry.
#include <cmath>
#include <vector>

#include "collide/bound_records.h"
#include "oracle/exact/distance_check.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_distance.h"
#include "oracle/exact/exact_polytope_distance.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/exact/rational.h"

namespace cc::exact {
namespace {

using harness::TermError;

double magnitude(const Rational& q) { return std::fabs(to_double(q)); }
Rational abs_of(const Rational& q) { return sgn(q) < 0 ? Rational(-q) : q; }

bool finite_vec(const Vec3& v) { return all_finite({v.x, v.y, v.z}); }
bool finite_triangle(const Triangle& t) { return all_finite(t); }

class Measure {
 public:
  explicit Measure(std::vector<TermError>& out) : out_(out) {}

  void term(std::string_view family, std::string_view term, double error, double bound, bool decisive = true) {
    out_.push_back({family, term, error, bound, decisive});
  }

  // A parameter (n1 - n2) / (d1 - d2) * 2^exponent: its rounding against the widening's term.
  void operator()(const bounds::Quotient& q) {
    if (!all_finite({q.n1, q.n2, q.d1, q.d2, q.t}) || q.d1 == q.d2) return;
    Rational exact = (rational(q.n1) - rational(q.n2)) / (rational(q.d1) - rational(q.d2));
    if (q.exponent > 0) mpq_mul_2exp(exact.get_mpq_t(), exact.get_mpq_t(), static_cast<unsigned long>(q.exponent));
    if (q.exponent < 0) mpq_div_2exp(exact.get_mpq_t(), exact.get_mpq_t(), static_cast<unsigned long>(-q.exponent));
    const double error = magnitude(rational(q.t) - exact);
    term(q.widening.name, "rounding", error, q.widening.rounding(q.t));
    term(q.widening.name, "total", error, q.widening.rounding(q.t) + fp::subnormal_slack);
  }

  // dist2 and reach2 of the scaled offset and reach, each against its term.
  void operator()(const bounds::SphereSquares& s) {
    if (!finite_vec(s.a.center) || !finite_vec(s.b.center) || !all_finite({s.a.radius, s.b.radius})) return;
    Rational scale = 1;
    if (s.exponent > 0) mpq_div_2exp(scale.get_mpq_t(), scale.get_mpq_t(), static_cast<unsigned long>(s.exponent));
    if (s.exponent < 0) mpq_mul_2exp(scale.get_mpq_t(), scale.get_mpq_t(), static_cast<unsigned long>(-s.exponent));
    const QVec3 d = scale * (rational(s.a.center) - rational(s.b.center));
    const Rational reach = scale * (rational(s.a.radius) + rational(s.b.radius));
    const Rational dist2 = dot(d, d), reach2 = reach * reach;
    const Rational e_dist = abs_of(rational(s.bound.dist2) - dist2), e_reach = abs_of(rational(s.bound.reach2) - reach2);
    const bool decisive = near(dist2 - reach2, s.bound.total());
    term("squares", "distance", to_double(e_dist), s.bound.distance(), decisive);
    term("squares", "reach", to_double(e_reach), s.bound.reach(), decisive);
    const Rational computed = rational(s.bound.dist2 - s.bound.reach2);
    term("squares", "total", magnitude(computed - (dist2 - reach2)), s.bound.total());
  }

  void operator()(const bounds::KdopProjection& k) {
    if (!finite_vec(k.point) || !all_finite({k.s, k.pad})) return;
    const QVec3 n{k.direction.x, k.direction.y, k.direction.z};
    const Rational exact = dot(n, rational(k.point));
    const double error = magnitude(rational(k.s) - exact);
    term("projection", "pad", error, k.pad);
    // The slab as widened must hold the exact projection.
    const Rational lo = rational(k.s - k.pad), hi = rational(k.s + k.pad);
    const double outside = exact < lo ? to_double(lo - exact) : (exact > hi ? to_double(exact - hi) : 0.0);
    term("projection", "total", outside > 0 ? INFINITY : error, k.pad);
  }

  // The axes of one static or moving OBB test.
  void operator()(const bounds::ObbTest& test, const std::vector<bounds::ObbAxis>& axes) {
    const Obb &a = test.a.box, &b = test.b.box;
    if (!all_finite(a) || !all_finite(b) || !finite_vec(test.a.velocity) || !finite_vec(test.b.velocity)) return;
    QVec3 ca[3], cb[3];
    Rational ha[3], hb[3], r[3][3], ta[3], tb[3], va[3], vb[3];
    const QVec3 d = rational(b.center) - rational(a.center);
    const QVec3 v = rational(test.b.velocity) - rational(test.a.velocity);
    for (int i = 0; i < 3; ++i) {
      ca[i] = rational(a.axes.col[i]), cb[i] = rational(b.axes.col[i]);
      ha[i] = rational(a.half[i]), hb[i] = rational(b.half[i]);
    }
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r[i][j] = dot(ca[i], cb[j]);
      ta[i] = dot(ca[i], d), tb[i] = dot(cb[i], d), va[i] = dot(ca[i], v), vb[i] = dot(cb[i], v);
    }
    const auto radius = [](const QVec3* cols, const Rational* half, const QVec3& l) {
      Rational sum = 0;
      for (int k = 0; k < 3; ++k) sum += half[k] * abs_of(dot(cols[k], l));
      return sum;
    };
    for (const bounds::ObbAxis& x : axes) {
      Rational p, q, ra, rb;
      QVec3 l;  // the axis the formula projects onto, exactly
      if (x.axis < 3) {
        const int i = x.axis;
        p = ta[i], q = va[i], ra = ha[i], l = ca[i];
        for (int j = 0; j < 3; ++j) rb += hb[j] * abs_of(r[i][j]);
      } else if (x.axis < 6) {
        const int j = x.axis - 3;
        p = tb[j], q = vb[j], rb = hb[j], l = cb[j];
        for (int i = 0; i < 3; ++i) ra += ha[i] * abs_of(r[i][j]);
      } else {
        const int i = (x.axis - 6) / 3, j = (x.axis - 6) % 3;
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        if (x.frame == 0) {
          p = ta[i2] * r[i1][j] - ta[i1] * r[i2][j];
          q = va[i2] * r[i1][j] - va[i1] * r[i2][j];
          l = r[i1][j] * ca[i2] - r[i2][j] * ca[i1];
        } else {
          p = r[i][j2] * tb[j1] - r[i][j1] * tb[j2];
          q = r[i][j2] * vb[j1] - r[i][j1] * vb[j2];
          l = r[i][j2] * cb[j1] - r[i][j1] * cb[j2];
        }
        ra = ha[i1] * abs_of(r[i2][j]) + ha[i2] * abs_of(r[i1][j]);
        rb = hb[j1] * abs_of(r[i][j2]) + hb[j2] * abs_of(r[i][j1]);
      }
      if (!all_finite({x.projection, x.rate, x.radius_a, x.radius_b})) continue;
      // Rounding: the projection at t = 0 and t = 1 and the radii, against the formula's exact value.
      const Rational dp = rational(x.projection) - p, dq = rational(x.rate) - q;
      const Rational dr = rational(x.radius_a + x.radius_b) - (ra + rb);
      const Rational rounding = std::max(abs_of(dp), abs_of(Rational(dp + dq))) + abs_of(dr);
      // Frame: the radii the formula takes for orthonormal axes against the parallelepipeds' true
      // radii along its axis (the formula's projection is exactly the offset's along it).
      const Rational true_radii = radius(ca, ha, l) + radius(cb, hb, l);
      const Rational frame = true_radii - (ra + rb);
      const double e_rounding = to_double(rounding), e_frame = sgn(frame) > 0 ? to_double(frame) : 0.0;
      // At its decision: the true gap |p + t q| - radii within a few bounds of 0 at some t of
      // the step (t = 0 for the static test).
      const double limit = test.bound.total();
      bool decisive = near(abs_of(p) - true_radii, limit) || near(abs_of(Rational(p + q)) - true_radii, limit);
      if (sgn(q) != 0) {
        for (const Rational& end : {Rational(true_radii - p), Rational(-true_radii - p)}) {
          const Rational t = end / q;
          decisive |= sgn(t) >= 0 && t <= 1;
        }
      }
      term("axis", "rounding", e_rounding, test.bound.rounding(), decisive);
      term("axis", "frame", e_frame, test.bound.frame(), decisive);
      term("axis", "total", e_rounding + e_frame, test.bound.total());
    }
  }

  void operator()(const bounds::SatAxis& s) {
    if (!finite_vec(s.axis) || !finite_triangle(s.b) || !std::isfinite(s.gap)) return;
    const QVec3 axis = rational(s.axis);
    ExactInterval pa;
    if (s.a_is_box) {
      if (!finite_vec(s.a_box.lo) || !finite_vec(s.a_box.hi)) return;
      for (int k = 0; k < 3; ++k) {
        const Rational lo = axis[k] * rational(s.a_box.lo[k]), hi = axis[k] * rational(s.a_box.hi[k]);
        pa.lo += std::min(lo, hi), pa.hi += std::max(lo, hi);
      }
    } else {
      if (!finite_triangle(s.a_triangle)) return;
      pa = project(s.a_triangle, axis);
    }
    const ExactInterval pb = project(s.b, axis);
    const Rational gap = std::max(Rational(pb.lo - pa.hi), Rational(pa.lo - pb.hi));
    const double error = magnitude(rational(s.gap) - gap);
    term("axis", "projection", error, s.bound.projection(), near(gap, s.bound.total()));
    term("axis", "total", error, s.bound.projection() + fp::subnormal_slack);
  }

  // The triangle in the box's frame: the coordinates' rounding, and how far the box's faces
  // move there for axes that are not orthonormal (the box is A^T A [-h, h] in that frame).
  void operator()(const bounds::FrameChange& f) {
    if (!finite_triangle(f.world) || !finite_triangle(f.local) || !all_finite(f.box)) return;
    QVec3 cols[3];
    for (int i = 0; i < 3; ++i) cols[i] = rational(f.box.axes.col[i]);
    const QVec3 center = rational(f.box.center);
    Rational change = 0;
    for (int k = 0; k < 3; ++k) {
      const QVec3 offset = rational(f.world.v[k]) - center;
      for (int i = 0; i < 3; ++i) change = std::max(change, abs_of(rational(f.local.v[k][i]) - dot(cols[i], offset)));
    }
    Rational orthonormality = 0;
    for (int i = 0; i < 3; ++i) {
      Rational moved = 0;
      for (int j = 0; j < 3; ++j) {
        const Rational gram = dot(cols[i], cols[j]) - (i == j ? 1 : 0);
        moved += abs_of(gram) * rational(f.box.half[j]);
      }
      orthonormality = std::max(orthonormality, moved);
    }
    const double e_change = to_double(change), e_orthonormality = to_double(orthonormality);
    term("frame change", "rounding", e_change, f.bound.rounding());
    term("frame change", "orthonormality", e_orthonormality, f.bound.orthonormality());
    term("frame change", "total", e_change + e_orthonormality, f.bound.total());
  }

  void operator()(const bounds::Independence& x) {
    if (!finite_vec(x.u) || !finite_vec(x.v) || !finite_vec(x.w) || !std::isfinite(x.det)) return;
    const Rational det = dot(cross(rational(x.u), rational(x.v)), rational(x.w));
    const double error = magnitude(rational(x.det) - det);
    term("coplanarity", "rounding", error, x.bound.rounding(), near(det, x.bound.total()));
    term("coplanarity", "total", error, x.bound.total());
  }

  void operator()(const bounds::RayTriangleSlab& s) {
    if (!finite_vec(s.origin) || !finite_triangle(s.triangle) || !finite_vec(s.axis) || !finite_vec(s.dir_scaled) ||
        !all_finite({s.projections[0], s.projections[1], s.projections[2], s.speed})) {
      return;
    }
    const QVec3 axis = rational(s.axis), origin = rational(s.origin);
    Rational projection = 0;
    for (int k = 0; k < 3; ++k) {
      projection = std::max(projection, abs_of(rational(s.projections[k]) - dot(axis, rational(s.triangle.v[k]) - origin)));
    }
    const double e_projection = to_double(projection);
    const double e_speed = magnitude(rational(s.speed) - dot(axis, rational(s.dir_scaled)));
    term("slab", "projection", e_projection, s.bound.projection());
    term("slab", "speed", e_speed, s.bound.speed());
    term("slab", "total", e_projection, s.bound.projection_total());
    term("slab", "total", e_speed, s.bound.speed_total());
  }

  // A face hit: how far from the triangle the point of the reported t lies, against half the pad
  // (the other half is for the volume tests). The pad's larger term takes the measure.
  void operator()(const bounds::RayMeshFaceHit& h) {
    if (!finite_vec(h.ray.origin) || !finite_vec(h.ray.dir) || !finite_triangle(h.triangle) || !std::isfinite(h.t)) return;
    const QVec3 point = rational(h.ray.origin) + rational(h.t) * rational(h.ray.dir);
    const double distance = std::sqrt(to_double(squared_distance(point, h.triangle)));
    if (h.pad.origin() >= h.pad.mesh()) {
      term("face hit", "origin", distance, h.pad.origin() / 2);
    } else {
      term("face hit", "mesh", distance, h.pad.mesh() / 2);
    }
    term("face hit", "total", distance, h.pad.total() / 2);
  }

  // apply(pose, point): the larger of the bound's terms takes the measure. At its decision when
  // the point is an extreme of the placed points on some axis (it makes the fitted box).
  void operator()(const bounds::Placement& p, const Aabb& extremes) {
    const RigidTransform& t = p.pose;
    if (!finite_vec(p.point) || !finite_vec(p.placed) || !finite_vec(t.translation) || !finite_vec(t.rotation.col[0]) ||
        !finite_vec(t.rotation.col[1]) || !finite_vec(t.rotation.col[2])) {
      return;
    }
    const double error = placement_error(t, p.point, p.placed);
    bool decisive = false;
    for (int k = 0; k < 3; ++k) decisive |= p.placed[k] == extremes.lo[k] || p.placed[k] == extremes.hi[k];
    if (p.bound.rotation_term() >= p.bound.translation_term()) {
      term("placement", "rotation", error, p.bound.rotation_term(), decisive);
    } else {
      term("placement", "translation", error, p.bound.translation_term(), decisive);
    }
    term("placement", "total", error, p.bound.total());
  }

  // sqrt(v . v) as computed against |v|; the padded radius must reach |v|. At its decision for
  // the largest root (the radius).
  void operator()(const bounds::RadiusRoot& r, double largest_root) {
    if (!finite_vec(r.vertex) || !std::isfinite(r.root) || !std::isfinite(r.padded)) return;
    const Rational length2 = dot(rational(r.vertex), rational(r.vertex));
    const double length = std::sqrt(to_double(length2));
    // |root - |v|| = |root^2 - |v|^2| / (root + |v|), to double precision.
    const double error = r.root + length > 0 ? magnitude(rational(r.root) * rational(r.root) - length2) / (r.root + length) : 0;
    term("radius", "rounding", error, r.padded - r.root, r.root == largest_root);
    const bool reaches = rational(r.padded) * rational(r.padded) >= length2;
    term("radius", "total", reaches ? error : INFINITY, r.padded - r.root);
  }

  // The cube around the placed vertices (those rotation_radius measured): how far a rotated
  // vertex reaches beyond its length |v| against the orthonormality term (the radius's own
  // rounding covers |v|), apply()'s rounding against the transform term, and the exact
  // placement inside the cube.
  void operator()(const bounds::Cube& c, const std::vector<bounds::RadiusRoot>& roots,
                  const std::vector<bounds::Placement>& placements) {
    const RigidTransform& t = c.pose;
    if (!std::isfinite(c.bound.radius) || !finite_vec(c.cube.lo) || !finite_vec(c.cube.hi) || !finite_vec(t.translation)) {
      return;
    }
    QVec3 rows[3];
    for (int k = 0; k < 3; ++k) rows[k] = rational(t.rotation.row(k));
    for (const bounds::RadiusRoot& r : roots) {
      if (!finite_vec(r.vertex)) continue;
      const QVec3 v = rational(r.vertex);
      const Rational length2 = dot(v, v);
      Rational beyond2 = 0, outside = 0;  // the largest rotated coordinate^2 - |v|^2
      for (int k = 0; k < 3; ++k) {
        const Rational rotated = dot(rows[k], v);
        beyond2 = std::max(beyond2, Rational(rotated * rotated - length2));
        const Rational placed = rotated + rational(t.translation[k]);
        outside = std::max({outside, Rational(rational(c.cube.lo[k]) - placed), Rational(placed - rational(c.cube.hi[k]))});
      }
      // |R v|_k - |v| = (|R v|_k^2 - |v|^2) / (|R v|_k + |v|), to double precision.
      const double e_beyond = sgn(beyond2) > 0 ? to_double(beyond2) / (2 * std::sqrt(to_double(length2))) : 0.0;
      term("cube", "orthonormality", e_beyond, c.bound.orthonormality());
      term("cube", "total", sgn(outside) > 0 ? INFINITY : e_beyond, c.bound.orthonormality());
    }
    for (const bounds::Placement& p : placements) {
      if (!(p.pose == t) || !finite_vec(p.point) || !finite_vec(p.placed)) continue;
      const double error = placement_error(t, p.point, p.placed);
      term("cube", "placement", error, c.bound.transform.total());
      const bool inside = test_aabb_aabb(c.cube, {p.placed, p.placed});
      term("cube", "total", inside ? 0.0 : INFINITY, c.bound.transform.total());
    }
  }

  // A distance answer: its distance's error against the exact signed distance, each witness's
  // distance from its shape's boundary, each against its rounding term where the rounding is the
  // only error (balls; boxes with exactly orthonormal axes) and against the whole bound.
  void operator()(const bounds::SphereSeparation& r) {
    if (!finite_vec(r.a.center) || !finite_vec(r.b.center) || !all_finite({r.a.radius, r.b.radius})) return;
    const QVec3 d = rational(r.b.center) - rational(r.a.center);
    distance(r.answer, {dot(d, d), 1, rational(r.a.radius) + rational(r.b.radius)}, r.bound.rounding());
    const double off = std::max(off_sphere(r.answer.on_a, r.a), off_sphere(r.answer.on_b, r.b));
    term("witness", "rounding", off, r.bound.point_rounding());
    term("witness", "total", off, r.answer.point_error);
  }

  void operator()(const bounds::SphereObbSeparation& r) {
    if (!finite_vec(r.a.center) || !all_finite({r.a.radius}) || !all_finite(r.b)) return;
    const QVec3 c = rational(r.a.center);
    const bool inside = in_box(c, r.b);
    const ExactSignedDistance exact{inside ? squared_depth_in_box(c, r.b) : squared_distance_to_box(c, r.b), inside ? -1 : 1,
                                    rational(r.a.radius)};
    const bool orthonormal = exactly_orthonormal(r.b.axes);
    distance(r.answer, exact, orthonormal ? r.bound.rounding() : -1);
    const double off = std::max(off_sphere(r.answer.on_a, r.a), off_box(r.answer.on_b, r.b));
    if (orthonormal) term("witness", "rounding", off, r.bound.point_rounding());
    term("witness", "total", off, r.answer.point_error);
  }

  // Two triangles: the distance against its certified bound (the total alone: it is certified
  // after the fact), each witness's distance from its triangle against the rounding term.
  void operator()(const bounds::TriangleSeparation& r) {
    if (!finite_triangle(r.a) || !finite_triangle(r.b)) return;
    distance(r.answer, {squared_distance_between_triangles(r.a, r.b)}, -1);
    const double off = std::max(off_triangle(r.answer.on_a, r.a), off_triangle(r.answer.on_b, r.b));
    term("witness", "rounding", off, r.bound.point_rounding());
    term("witness", "total", off, r.answer.point_error);
  }

  // Two boxes: the signed distance against its whole bound (certified after the fact apart; the
  // depth's terms overlapping), each witness's distance from its box's boundary.
  void operator()(const bounds::ObbSeparation& r) {
    if (!all_finite(r.a) || !all_finite(r.b)) return;
    const auto ca = box_corners(r.a), cb = box_corners(r.b);
    distance(r.answer, exact_polytope_distance(ca, cb), -1);
    const double off = std::max(off_box(r.answer.on_a, r.a), off_box(r.answer.on_b, r.b));
    term("witness", "total", off, r.answer.point_error);
  }

  // A triangle and a box: the signed distance against its whole bound, each witness's distance
  // from its shape (the box's boundary).
  void operator()(const bounds::TriangleBoxSeparation& r) {
    if (!finite_triangle(r.triangle) || !all_finite(r.box)) return;
    const auto ct = triangle_corners(r.triangle);
    const auto cb = box_corners(r.box);
    distance(r.answer, exact_polytope_distance(ct, cb), -1);
    const double off = std::max(off_triangle(r.answer.on_a, r.triangle), off_box(r.answer.on_b, r.box));
    term("witness", "total", off, r.answer.point_error);
  }

 private:
  // |x - exact| for a double x, rounded up to a double: the least double e with x within e of
  // the exact signed distance, decided on squares (root_within).
  static double error_of(double x, const ExactSignedDistance& exact) {
    const Rational y = exact.sign * (rational(x) + exact.reach);
    const auto short_of = [&](double e) { return e < 0 || !root_within(exact.squared, y, rational(e)); };
    const double estimate = std::fabs(x - rounded_down(exact));
    return std::nextafter(largest_double_where(short_of, estimate), INFINITY);
  }

  // The signed distance's error, against the rounding term (when >= 0) and the whole bound.
  void distance(const Separation& s, const ExactSignedDistance& exact, double rounding) {
    if (!std::isfinite(s.distance)) return;
    const double error = error_of(s.distance, exact);
    if (rounding >= 0) term("signed distance", "rounding", error, rounding);
    term("signed distance", "total", error, s.distance_error);
  }

  // How far a point lies from a ball's sphere, and from a box's boundary.
  static double off_sphere(const Vec3& p, const Sphere& s) {
    const QVec3 d = rational(p) - rational(s.center);
    return error_of(0, {dot(d, d), 1, rational(s.radius)});
  }
  static double off_triangle(const Vec3& p, const Triangle& t) {
    return error_of(0, {squared_distance_to_triangle(rational(p), t)});
  }
  static double off_box(const Vec3& p, const Obb& b) {
    const QVec3 q = rational(p);
    return error_of(0, {in_box(q, b) ? squared_depth_in_box(q, b) : squared_distance_to_box(q, b)});
  }

  // Whether the axes are orthonormal in exact arithmetic (a permutation of the coordinate axes,
  // with signs): the frame term covers nothing then.
  static bool exactly_orthonormal(const Mat3& axes) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (dot(rational(axes.col[i]), rational(axes.col[j])) != (i == j ? 1 : 0)) return false;
      }
    }
    return true;
  }

  // How many bounds from its threshold a quantity may be and still be at its decision.
  static constexpr double kNear = 4;

  static bool near(const Rational& value, double limit) { return magnitude(value) <= kNear * limit; }

  struct ExactInterval {
    Rational lo = 0, hi = 0;
  };

  static ExactInterval project(const Triangle& t, const QVec3& axis) {
    ExactInterval out;
    for (int k = 0; k < 3; ++k) {
      const Rational p = dot(axis, rational(t.v[k]));
      if (k == 0 || p < out.lo) out.lo = p;
      if (k == 0 || p > out.hi) out.hi = p;
    }
    return out;
  }

  // The largest error of a placed point against rotation * point + translation.
  static double placement_error(const RigidTransform& t, const Vec3& point, const Vec3& placed) {
    const QVec3 p = rational(point);
    Rational error = 0;
    for (int k = 0; k < 3; ++k) {
      const Rational exact = dot(rational(t.rotation.row(k)), p) + rational(t.translation[k]);
      error = std::max(error, abs_of(rational(placed[k]) - exact));
    }
    return to_double(error);
  }

  // The squared distance from p to the segment [a, b] (a point when a == b).
  static Rational squared_distance_to_segment(const QVec3& p, const QVec3& a, const QVec3& b) {
    const QVec3 ab = b - a, ap = p - a;
    const Rational length2 = dot(ab, ab);
    Rational s = length2 == 0 ? Rational(0) : Rational(dot(ap, ab) / length2);
    s = std::clamp(s, Rational(0), Rational(1));
    const QVec3 off = ap - s * ab;
    return dot(off, off);
  }

  // The squared distance from p to the closed triangle: to its plane when p projects inside it,
  // else to its nearest edge (degenerate triangles are their edges).
  static Rational squared_distance(const QVec3& p, const Triangle& t) {
    const QVec3 v[3] = {rational(t.v[0]), rational(t.v[1]), rational(t.v[2])};
    Rational best = squared_distance_to_segment(p, v[0], v[1]);
    best = std::min(best, squared_distance_to_segment(p, v[1], v[2]));
    best = std::min(best, squared_distance_to_segment(p, v[2], v[0]));
    const QVec3 n = cross(v[1] - v[0], v[2] - v[0]);
    if (is_zero(n)) return best;
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside &= sgn(dot(cross(v[(k + 1) % 3] - v[k], p - v[k]), n)) >= 0;
    if (!inside) return best;
    const Rational h = dot(n, p - v[0]);
    return std::min(best, Rational(h * h / dot(n, n)));
  }

  std::vector<TermError>& out_;
};

}  // namespace

std::vector<TermError> ExactRationalReference::bound_errors(const bounds::Records& records) const {
  std::vector<TermError> out;
  Measure measure(out);
  for (const auto& r : records.quotients) measure(r);
  for (const auto& r : records.spheres) measure(r);
  for (const auto& r : records.kdop_projections) measure(r);
  for (std::size_t i = 0; i < records.obb_tests.size(); ++i) measure(records.obb_tests[i], records.obb_axes[i]);
  for (const auto& r : records.sat_axes) measure(r);
  for (const auto& r : records.frame_changes) measure(r);
  for (const auto& r : records.independences) measure(r);
  for (const auto& r : records.ray_triangle_slabs) measure(r);
  for (const auto& r : records.ray_mesh_hits) measure(r);
  Aabb extremes{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  for (const auto& r : records.placements) {
    for (int k = 0; k < 3; ++k) {
      extremes.lo[k] = std::min(extremes.lo[k], r.placed[k]), extremes.hi[k] = std::max(extremes.hi[k], r.placed[k]);
    }
  }
  for (const auto& r : records.placements) measure(r, extremes);
  double largest_root = 0;
  for (const auto& r : records.radius_roots) largest_root = std::max(largest_root, r.root);
  for (const auto& r : records.radius_roots) measure(r, largest_root);
  for (const auto& r : records.cubes) measure(r, records.radius_roots, records.placements);
  for (const auto& r : records.sphere_separations) measure(r);
  for (const auto& r : records.sphere_obb_separations) measure(r);
  for (const auto& r : records.triangle_separations) measure(r);
  for (const auto& r : records.obb_separations) measure(r);
  for (const auto& r : records.triangle_box_separations) measure(r);
  return out;
}

}  // namespace cc::exact
