// ray_mesh in exact arithmetic: every face near the ray is tested exactly (its first point, and
// the margin of the ray's segment against it by the exact separating-axis test); the first
// point over the mesh is the answer, and a hit's t must lie between that point and the ray's
// entry into the box of a face it may name, grown by the library's band.
#include <algorithm>
#include <cmath>
#include <map>

#include "harness/judging/bands.h"
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_meshes.h"
#include "oracle/exact/exact_ray_triangle.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

constexpr int kMinExponent = -300, kMaxExponent = 300;

// Whether the ray (in doubles, each parameter interval widened by 2^-40 of its ends) comes into
// the box grown by pad: conservative, since the rounding of the slabs is far below pad.
bool may_reach(const Ray& ray, const Aabb& box, double pad) {
  double enter = ray.tmin, exit = ray.tmax;
  for (int k = 0; k < 3; ++k) {
    const double lo = box.lo[k] - pad, hi = box.hi[k] + pad;
    if (ray.dir[k] == 0) {
      if (ray.origin[k] < lo || ray.origin[k] > hi) return false;
      continue;
    }
    double t1 = (lo - ray.origin[k]) / ray.dir[k], t2 = (hi - ray.origin[k]) / ray.dir[k];
    if (t1 > t2) std::swap(t1, t2);
    enter = std::max(enter, t1 - 0x1p-40 * std::fabs(t1));
    exit = std::min(exit, t2 + 0x1p-40 * std::fabs(t2));
  }
  return enter <= exit;
}

Aabb box_of(const Triangle& t) {
  Aabb b{t.v[0], t.v[0]};
  for (const Vec3& p : t.v) {
    for (int k = 0; k < 3; ++k) b.lo[k] = std::min(b.lo[k], p[k]), b.hi[k] = std::max(b.hi[k], p[k]);
  }
  return b;
}

// The parameter range of the ray inside the box grown by pad (exact), if it meets it.
std::optional<std::pair<std::optional<Rational>, std::optional<Rational>>> range_in(const ExactRay& r, const Aabb& box,
                                                                                    const Rational& pad) {
  std::optional<Rational> enter = r.tmin, exit = r.tmax;
  for (int k = 0; k < 3; ++k) {
    const Rational lo = rational(box.lo[k]) - pad, hi = rational(box.hi[k]) + pad;
    if (sgn(r.d[k]) == 0) {
      if (r.o[k] < lo || r.o[k] > hi) return std::nullopt;
      continue;
    }
    Rational t1 = (lo - r.o[k]) / r.d[k], t2 = (hi - r.o[k]) / r.d[k];
    if (t1 > t2) std::swap(t1, t2);
    if (!enter || t1 > *enter) enter = t1;
    if (!exit || t2 < *exit) exit = t2;
  }
  if (enter && exit && *enter > *exit) return std::nullopt;
  return std::pair{enter, exit};
}


}  // namespace

template <>
ExactVerdict judge(const harness::RayMeshInput& in) {
  const Ray& ray = in.ray;
  if (!all_finite({ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z}) ||
      has_nan({ray.tmin, ray.tmax})) {
    return documented(false, "NaN or infinite ray");
  }
  if (ray.tmin > ray.tmax || ray.tmin == INFINITY || ray.tmax == -INFINITY) return documented(false, "empty range of t");
  const Mesh& mesh = *in.mesh.mesh;
  if (auto problem = mesh_problem(mesh)) return unspecified("mesh: " + *problem);
  double magnitude = max_abs(ray.origin);
  for (const Vec3& p : mesh.vertices) magnitude = std::max(magnitude, max_abs(p));
  if (auto why = scale_outside(magnitude, kMinExponent, kMaxExponent)) return unspecified(*why);
  // A zero direction is the origin alone, hit at tmin (which may be -inf).
  const bool point = ray.dir == Vec3{};
  const double scale = scale_of(magnitude);

  const ExactRay r = exact_ray(ray);
  const double band = harness::library_band(harness::QueryKind::ray_mesh).width;
  const Rational reach = rational(band * scale);
  ExactVerdict v;
  v.unlisted_margin = -kNearMargin;
  std::optional<Rational> first;  // the first point over the mesh
  std::optional<Rational> earliest;  // the earliest entry into a face's box grown by the band
  bool earliest_unbounded = false;
  for (std::uint32_t f = 0; f < mesh.size(); ++f) {
    const Triangle tri = mesh.triangle(f);
    const Aabb box = box_of(tri);
    if (!may_reach(ray, box, kNearMargin * scale)) continue;
    const auto range = range_in(r, box, rational(kNearMargin * scale));
    if (!range) continue;
    // The segment of the ray near this face (its ends finite), against the face.
    const QVec3 p0 = range->first ? r.at(*range->first) : r.o, p1 = range->second ? r.at(*range->second) : r.o;
    const std::array<QVec3, 3> v3 = exact_triangle(tri);
    const SatResult sat = exact_sat(rational_triangle_shape(v3[0], v3[1], v3[2], "T"), rational_triangle_shape(p0, p1, p1, "R"));
    const double margin = sat.margin / scale;
    std::optional<Rational> t;
    if (point) {
      if (sgn(distance2_to_triangle(r.o, v3)) == 0) t = Rational(0);  // (stands for tmin)
    } else {
      t = exact_first_hit(r, v3);
    }
    if (t) {
      v.answer.pairs.emplace_back(f, 0);
      if (!first || *t < *first) first = t;
    }
    if (t || margin >= -kNearMargin) v.pair_margins.push_back({{f, 0}, t ? std::max(margin, 0.0) : std::min(margin, -0x1p-1074)});
    if (t || margin >= -band) {
      const auto grown = range_in(r, box, reach);
      if (grown && !grown->first) earliest_unbounded = true;
      if (grown && grown->first && (!earliest || *grown->first < *earliest)) earliest = grown->first;
    }
  }
  v.answer.hit = first.has_value();
  v.margin = v.unlisted_margin;
  for (const harness::PairMargin& pm : v.pair_margins) {
    if (std::fabs(pm.margin) < std::fabs(v.margin)) v.margin = pm.margin;
  }
  if (first && point) {
    v.answer.params = {ray.tmin};
    v.param_ranges = {{ray.tmin, ray.tmin}};
  } else if (first) {
    v.answer.params = {to_double(*first)};
    const double lowest = earliest_unbounded || !earliest ? -INFINITY : round_down(*earliest);
    v.param_ranges = {{lowest, round_up(*first)}};
  }
  return v;
}

// The faces near the ray, each with its exact first point and its margin.
template <>
harness::Explanation explain(const harness::RayMeshInput& in) {
  using harness::Explanation;
  const harness::ExactVerdict v = judge(in);
  Explanation e;
  e.title = "faces near the ray (segment against triangle, exact separating axes)";
  if (v.contract != harness::Contract::in) {
    e.deciding = v.note;
    return e;
  }
  e.columns = {"face", "hit", "margin"};
  for (const harness::PairMargin& p : v.pair_margins) {
    const bool hit = std::binary_search(v.answer.pairs.begin(), v.answer.pairs.end(), p.pair);
    e.rows.push_back({std::to_string(p.pair.first), hit ? "yes" : "no", num(p.margin)});
    if (std::fabs(p.margin) == std::fabs(v.margin)) e.deciding_row = static_cast<int>(e.rows.size()) - 1;
  }
  e.facts.push_back({"faces", std::to_string(in.mesh.mesh->size())});
  e.facts.push_back({"faces near the ray", std::to_string(v.pair_margins.size())});
  if (v.answer.hit) {
    e.facts.push_back({"first t (exact, rounded)", num(v.answer.params[0])});
    e.facts.push_back({"t allowed", interval(v.param_ranges[0].first, v.param_ranges[0].second)});
  }
  e.deciding = "the face nearest the boundary";
  e.deciding_value = v.margin;
  return e;
}

}  // namespace cc::exact
