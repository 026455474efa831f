#include "collide/ray_triangle.h"

#include <algorithm>
#include <cmath>

#include "collide/ray_triangle_bound.h"
#include "collide/record_sink.h"

namespace cc {
namespace {

// How it works. Any slab that contains the triangle in exact arithmetic holds every point of
// the ray that lies in the triangle, so clipping the ray's parameter range against such slabs
// never loses a hit, whichever slabs are used and however their normals were rounded. Each
// slab is therefore fitted to the triangle's own projections and widened by their rounding
// error, and the ray's speed across it is taken as an interval: that is all that conservative
// needs. Which slabs are used decides how tight the answer is: the plane, the in-plane normals
// of the edges and the edges themselves pin a point to within a few roundings of the triangle;
// for triangles that are segments or points, the planes through the direction and an edge, the
// in-plane normals of those, and the plane through the direction towards the triangle do. (The
// coordinate axes come first: cheap, they decide most far misses.)
//
// The ray is moved to the origin (the vertices become v - origin, each coordinate rounded once,
// an error the slabs' widening includes) and its direction scaled by a power of two to a
// largest component in [1, 2), so that a unit of t is about a unit of space.

// Each slab bound is widened by its rounding, and the speed across it taken as an interval
// (bounds::RayTriangleSlabBound); a parameter bound (one division) is moved outward by more than
// its rounding (bounds::kRayTriangleParameter).
double lower(double t) { return bounds::kRayTriangleParameter.lower(t); }
double upper(double t) { return bounds::kRayTriangleParameter.upper(t); }

// hi + lo == the exact result (Knuth's two-sum, and the product through a fused multiply-add).
struct TwoTerm {
  double hi, lo;
};
TwoTerm two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
TwoTerm two_product(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

// A difference of two points held exactly: hi + lo per component.
struct ExactVec {
  Vec3 hi, lo;
};

ExactVec exact_difference(const Vec3& a, const Vec3& b) {
  ExactVec out;
  for (int i = 0; i < 3; ++i) {
    const TwoTerm s = two_sum(a[i], -b[i]);
    out.hi[i] = s.hi, out.lo[i] = s.lo;
  }
  return out;
}

// a scaled by the power of two that brings max |a.hi| into [1, 2) (then short vectors do not
// underflow in products); 0 stays 0.
ExactVec unit_scaled(const ExactVec& a) {
  const double m = max_abs(a.hi);
  if (m == 0) return a;
  const int e = std::ilogb(m);
  ExactVec out;
  for (int i = 0; i < 3; ++i) out.hi[i] = std::ldexp(a.hi[i], -e), out.lo[i] = std::ldexp(a.lo[i], -e);
  return out;
}

// The direction of a x b for exactly held a and b, accurate to about u + u^2 / sin(angle
// between them): the leading products are exact, so nearly parallel vectors (the edges of a
// sliver, a direction along an edge) still give a normal that is normal. Unit-scaled.
Vec3 accurate_cross(const ExactVec& a_in, const ExactVec& b_in) {
  const ExactVec a = unit_scaled(a_in), b = unit_scaled(b_in);
  Vec3 out;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const TwoTerm p = two_product(a.hi[i], b.hi[j]), q = two_product(a.hi[j], b.hi[i]);
    const TwoTerm s = two_sum(p.hi, -q.hi);
    const double small = (p.lo - q.lo) + ((a.hi[i] * b.lo[j] - a.hi[j] * b.lo[i]) + (a.lo[i] * b.hi[j] - a.lo[j] * b.hi[i]));
    out[k] = s.hi + (s.lo + small);
  }
  return unit_scaled(out);
}

Vec3 scaled_cross(const Vec3& a, const Vec3& b) { return unit_scaled(cross(a, b)); }

// t * 2^e rounded down (up): a parameter moved into the scaled units without losing a hit.
double scaled_down(double t, int e) {
  const double s = std::ldexp(t, e);
  return std::isfinite(s) && std::ldexp(s, -e) != t ? std::nextafter(s, -INFINITY) : s;
}
double scaled_up(double t, int e) {
  const double s = std::ldexp(t, e);
  return std::isfinite(s) && std::ldexp(s, -e) != t ? std::nextafter(s, INFINITY) : s;
}

// The parameters still possible on one half line of the ray, t >= 0 (forward) or, for the
// reversed ray, t' = -t >= 0 (backward): on a half line every slab leaves an interval.
struct HalfLine {
  double lo, hi;
  bool active;

  // Empty also when lo = +inf: a parallel slab that the ray never reaches leaves no parameter.
  bool empty() const { return !active || !(lo <= hi) || lo == INFINITY; }

  // Keeps the t in [lo, hi] for which t * speed may lie in [slab_lo, slab_hi], the speed
  // being anywhere in [q - q_error, q + q_error].
  template <class Records>
  void clip(double slab_lo, double slab_hi, double q, double q_error, Records& records) {
    if (!active) return;
    const double q_lo = q - q_error, q_hi = q + q_error;
    const auto divide = [&records](double n, double d) {
      const double t = n / d;
      records.add(bounds::Quotient{n, 0, d, 0, 0, t, bounds::kRayTriangleParameter});
      return t;
    };
    double enter, exit;
    if (q_lo > 0) {  // moving up across the slab
      enter = slab_lo >= 0 ? divide(slab_lo, q_hi) : divide(slab_lo, q_lo);
      exit = slab_hi >= 0 ? divide(slab_hi, q_lo) : divide(slab_hi, q_hi);
    } else if (q_hi < 0) {  // moving down across it
      enter = slab_hi <= 0 ? divide(slab_hi, q_lo) : divide(slab_hi, q_hi);
      exit = slab_lo <= 0 ? divide(slab_lo, q_hi) : divide(slab_lo, q_lo);
    } else {  // parallel, or nearly: t * [q_lo, q_hi] holds 0 and widens as t grows
      exit = INFINITY;
      if (slab_lo > 0) {
        enter = q_hi > 0 ? divide(slab_lo, q_hi) : INFINITY;
      } else if (slab_hi < 0) {
        enter = q_lo < 0 ? divide(slab_hi, q_lo) : INFINITY;
      } else {
        enter = -INFINITY;
      }
    }
    lo = std::max(lo, lower(enter));
    hi = std::min(hi, upper(exit));
  }
};

// `ray` and `triangle` as given, for the records.
template <class Records>
class SlabClipper {
 public:
  SlabClipper(const Ray& ray, const Triangle& triangle, const Triangle& translated, const Vec3& dir, HalfLine forward,
              HalfLine backward, Records& records)
      : ray_(ray), triangle_(triangle), translated_(translated), v_(translated.v), dir_(dir), forward_(forward),
        backward_(backward), records_(records) {
    for (const Vec3& p : v_) reach_ = std::max(reach_, max_abs(p));
  }

  // Clips both half lines by the slab of the triangle along `axis`; false when nothing is left.
  bool clip(const Vec3& axis) {
    if (axis == Vec3{}) return true;  // a zero axis constrains nothing
    const double p0 = dot(axis, v_[0]), p1 = dot(axis, v_[1]), p2 = dot(axis, v_[2]);
    const double q = dot(axis, dir_);
    bool products = false;  // a nonzero product of components may have underflowed
    for (int i = 0; i < 3; ++i) products |= axis[i] != 0 && dir_[i] != 0;
    const bounds::RayTriangleSlabBound bound{norm1(axis), reach_, dot(abs(axis), abs(dir_)), products};
    records_.add(bounds::RayTriangleSlab{ray_.origin, triangle_, translated_, dir_, axis, {p0, p1, p2}, q, bound});
    const double widen = bound.projection_total();
    const double slab_lo = std::min({p0, p1, p2}) - widen, slab_hi = std::max({p0, p1, p2}) + widen;
    const double q_error = bound.speed_total();
    forward_.clip(slab_lo, slab_hi, q, q_error, records_);
    backward_.clip(slab_lo, slab_hi, -q, q_error, records_);
    return !(forward_.empty() && backward_.empty());
  }

  // The first parameter left (in the scaled units), if any.
  bool first(double& t) const {
    if (!backward_.empty()) {
      t = -backward_.hi;
      return true;
    }
    if (!forward_.empty()) {
      t = forward_.lo;
      return true;
    }
    return false;
  }

 private:
  const Ray& ray_;
  const Triangle &triangle_, &translated_;
  std::array<Vec3, 3> v_;
  Vec3 dir_;
  HalfLine forward_, backward_;
  Records& records_;
  double reach_ = 0;  // the largest |coordinate| of a translated vertex
};

template <class Records>
RayTriangleHit intersect(const Ray& ray, const Triangle& triangle, Records& records) {
  if (!finite(ray.origin) || !finite(ray.dir) || !finite(triangle)) return {};
  if (!(ray.tmin <= ray.tmax) || ray.tmin == INFINITY || ray.tmax == -INFINITY) return {};  // NaN too

  const double m = max_abs(ray.dir);
  const int e = m > 0 ? std::ilogb(m) : 0;
  const Vec3 d{std::ldexp(ray.dir.x, -e), std::ldexp(ray.dir.y, -e), std::ldexp(ray.dir.z, -e)};
  const double tmin = scaled_down(ray.tmin, e), tmax = scaled_up(ray.tmax, e);
  const HalfLine forward{std::max(tmin, 0.0), tmax, tmax >= 0};
  const HalfLine backward{std::max(-tmax, 0.0), -tmin, tmin < 0};

  const auto& v = triangle.v;
  const Triangle translated{{v[0] - ray.origin, v[1] - ray.origin, v[2] - ray.origin}};
  SlabClipper<Records> clipper(ray, triangle, translated, d, forward, backward, records);

  // The triangle's bounding box first: cheap, and it decides most far misses.
  if (!clipper.clip({1, 0, 0}) || !clipper.clip({0, 1, 0}) || !clipper.clip({0, 0, 1})) return {};

  const ExactVec exact_edge[3] = {exact_difference(v[1], v[0]), exact_difference(v[2], v[1]),
                                  exact_difference(v[0], v[2])};
  const Vec3 edge[3] = {unit_scaled(exact_edge[0].hi), unit_scaled(exact_edge[1].hi), unit_scaled(exact_edge[2].hi)};
  const Vec3 normal = accurate_cross(exact_edge[0], exact_edge[1]);

  // The ray's extent, the plane, the in-plane edge normals: these decide most misses.
  if (!clipper.clip(d) || !clipper.clip(normal)) return {};
  for (const Vec3& g : edge) {
    if (!clipper.clip(scaled_cross(normal, g))) return {};
  }
  // The edges, against overshooting a sharp corner.
  for (const Vec3& g : edge) {
    if (!clipper.clip(g)) return {};
  }
  // The planes through the direction and an edge, and their normals in their plane: a
  // triangle that is (nearly) a segment, and rays along or across one.
  const ExactVec exact_dir{d, {}};
  for (int i = 0; i < 3; ++i) {
    const Vec3 across = accurate_cross(exact_dir, exact_edge[i]);
    if (!clipper.clip(across) || !clipper.clip(scaled_cross(across, edge[i]))) return {};
  }
  // The triangle's centre as seen across the ray: a triangle that is (nearly) a point.
  const auto mean = [&translated](int k) {
    return fp::sum3(translated.v[0][k], translated.v[1][k], translated.v[2][k]) / 3;
  };
  const Vec3 centre = unit_scaled(Vec3{mean(0), mean(1), mean(2)});
  if (!clipper.clip(scaled_cross(scaled_cross(d, centre), d))) return {};
  if (d == Vec3{}) {  // the origin alone: towards the triangle, and across each edge towards it
    if (!clipper.clip(centre)) return {};
    for (const Vec3& g : edge) {
      if (!clipper.clip(scaled_cross(scaled_cross(g, centre), g))) return {};
    }
  }

  double t = 0;
  if (!clipper.first(t)) return {};
  // Back to the caller's units, rounded down, within [tmin, tmax] as given.
  double unscaled = std::ldexp(t, -e);
  if (std::isfinite(unscaled) && std::ldexp(unscaled, e) != t) unscaled = std::nextafter(unscaled, -INFINITY);
  return {true, std::min(std::max(unscaled, ray.tmin), ray.tmax) + 0.0};
}

}  // namespace

RayTriangleHit intersect_ray_triangle(const Ray& ray, const Triangle& triangle) {
  bounds::NoRecords none;
  return intersect(ray, triangle, none);
}

RayTriangleHit intersect_ray_triangle(const Ray& ray, const Triangle& triangle, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return intersect(ray, triangle, into);
}

}  // namespace cc
