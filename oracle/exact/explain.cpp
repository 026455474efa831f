// The exact reference's reasoning, for triage: per kind, a table of the axes or slabs that
// decide, with exact values and the same quantities evaluated in floating point.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "collide/kdop.h"
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/exact_kdop_kdop.h"
#include "oracle/exact/exact_meshes.h"
#include "oracle/exact/exact_ray_aabb.h"
#include "oracle/exact/exact_sweep.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

using harness::Explanation;

std::string num(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}
std::string num(const Rational& q) { return num(to_double(q)); }
// (Built by appending: GCC 12 warns falsely about chains of string concatenations.)
std::string interval(double lo, double hi) {
  std::string s = "[";
  s.append(num(lo)).append(", ").append(num(hi)).append("]");
  return s;
}
std::string vec(const Vec3& v) {
  std::string s = "(";
  s.append(num(v.x)).append(", ").append(num(v.y)).append(", ").append(num(v.z)).append(")");
  return s;
}

// How many ULPs of `magnitude` the value is.
double in_ulps(double value, double magnitude) {
  const double m = std::fabs(magnitude);
  if (m == 0 || !std::isfinite(m)) return 0;
  const double ulp = std::nextafter(m, INFINITY) - m;
  return value / ulp;
}

// A shape's projection onto an axis, in plain floating point.
std::pair<double, double> project_in_double(const ExactShape& s, const Vec3& axis) {
  if (!s.vertices.empty()) {
    double lo = INFINITY, hi = -INFINITY;
    for (const QVec3& v : s.vertices) {
      const Vec3 p = to_double(v);
      const double x = axis.x * p.x + axis.y * p.y + axis.z * p.z;
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    return {lo, hi};
  }
  const Vec3 c = to_double(s.center);
  const double mid = axis.x * c.x + axis.y * c.y + axis.z * c.z;
  double radius = 0;
  for (const QVec3& h : s.half_edges) {
    const Vec3 e = to_double(h);
    radius += std::fabs(axis.x * e.x + axis.y * e.y + axis.z * e.z);
  }
  return {mid - radius, mid + radius};
}

Explanation explain_polytopes(const ExactShape& a, const ExactShape& b) {
  const SatResult r = exact_sat(a, b);
  Explanation e;
  e.title = "separating-axis candidates (rank of the edge directions: " + std::to_string(r.rank) + ")";
  e.columns = {"axis", "direction", "A", "B", "gap exact", "gap float", "gap/conditioning"};
  for (std::size_t i = 0; i < r.axes.size(); ++i) {
    const AxisReport& x = r.axes[i];
    const Vec3 axis = to_double(x.axis);
    const auto [alo, ahi] = project_in_double(a, axis);
    const auto [blo, bhi] = project_in_double(b, axis);
    const double gap_float = std::max(blo - ahi, alo - bhi);
    e.rows.push_back({x.name, vec(axis), interval(to_double(x.a.lo), to_double(x.a.hi)),
                      interval(to_double(x.b.lo), to_double(x.b.hi)), num(x.gap), num(gap_float),
                      num((Magnitude::of(x.gap) / x.conditioning).to_double())});
  }
  e.facts.push_back({"answer", r.hit ? "the shapes meet (no candidate axis separates them)"
                                     : "disjoint (a candidate axis separates them)"});
  if (r.deciding_axis >= 0) {
    const AxisReport& x = r.axes[static_cast<std::size_t>(r.deciding_axis)];
    e.deciding_row = r.deciding_axis;
    e.deciding = std::string(r.hit ? "smallest overlap" : "largest separation") + " on " + x.name;
    e.deciding_value = to_double(x.gap);
    const double magnitude = std::max({std::fabs(to_double(x.a.lo)), std::fabs(to_double(x.a.hi)),
                                       std::fabs(to_double(x.b.lo)), std::fabs(to_double(x.b.hi))});
    e.deciding_ulps = in_ulps(e.deciding_value, magnitude);
    e.axis = to_double(x.axis);
    e.a_lo = to_double(x.a.lo), e.a_hi = to_double(x.a.hi), e.b_lo = to_double(x.b.lo), e.b_hi = to_double(x.b.hi);
  }
  return e;
}

struct Explain {
  Explanation operator()(const harness::RayAabbInput& in) const {
    const RayAnalysis r = analyse_ray(in);
    Explanation e;
    e.title = "slabs: the t interval of each";
    e.columns = {"slab", "dir", "t interval exact", "t interval float", "note"};
    const char* const names[] = {"x", "y", "z"};
    for (const RaySlab& s : r.slabs) {
      const int k = s.axis;
      if (s.parallel) {
        e.rows.push_back({names[k], num(in.ray.dir[k]), "-", "-",
                          std::string("parallel: origin ") + (s.origin_inside ? "inside" : "outside") + " the closed slab"});
        continue;
      }
      const double inv = 1.0 / in.ray.dir[k];
      double t0 = (in.box.lo[k] - in.ray.origin[k]) * inv, t1 = (in.box.hi[k] - in.ray.origin[k]) * inv;
      if (inv < 0) std::swap(t0, t1);
      e.rows.push_back({names[k], num(in.ray.dir[k]), interval(to_double(s.near_t), to_double(s.far_t)), interval(t0, t1), ""});
    }
    e.facts.push_back({"[tmin, tmax]", interval(in.ray.tmin, in.ray.tmax)});
    e.facts.push_back({"t_enter (exact)", r.enter ? num(*r.enter) : "-inf"});
    e.facts.push_back({"t_exit (exact)", r.exit ? num(*r.exit) : "inf"});
    if (!r.flushed.empty()) e.facts.push_back({"parallel by contract", r.flushed});
    e.deciding = r.empty_range ? "tmin > tmax: no parameter at all" : "the box growth needed for contact, bound by " + r.binding;
    e.deciding_value = -to_double(r.delta);
    e.deciding_ulps = in_ulps(e.deciding_value, max_magnitude({in.ray.origin.x, in.ray.origin.y, in.ray.origin.z,
                                                                in.box.lo.x, in.box.lo.y, in.box.lo.z, in.box.hi.x,
                                                                in.box.hi.y, in.box.hi.z}));
    return e;
  }
  Explanation operator()(const harness::SphereSphereInput& in) const {
    Explanation e;
    const QVec3 d = rational(in.a.center) - rational(in.b.center);
    const Rational reach = rational(in.a.radius) + rational(in.b.radius);
    const Rational slack = reach * reach - dot(d, d);
    const Vec3 fd = in.a.center - in.b.center;
    const double fd2 = fd.x * fd.x + fd.y * fd.y + fd.z * fd.z, fr = in.a.radius + in.b.radius;
    e.title = "distances";
    e.facts = {{"|c_a - c_b|", num(length(d).to_double())},
               {"r_a + r_b", num(reach)},
               {"(r_a + r_b)^2 - |c_a - c_b|^2 exact", num(slack)},
               {"(r_a + r_b)^2 - |c_a - c_b|^2 float", num(fr * fr - fd2)}};
    e.deciding = "(r_a + r_b)^2 - |c_a - c_b|^2";
    e.deciding_value = to_double(slack);
    e.deciding_ulps = in_ulps(e.deciding_value, std::max(to_double(reach * reach), to_double(dot(d, d))));
    return e;
  }
  Explanation operator()(const harness::AabbAabbInput& in) const {
    Explanation e;
    e.title = "axes";
    e.columns = {"axis", "A", "B", "overlap"};
    const char* const names[] = {"x", "y", "z"};
    double worst = INFINITY;
    for (int k = 0; k < 3; ++k) {
      const double overlap = std::min(in.a.hi[k], in.b.hi[k]) - std::max(in.a.lo[k], in.b.lo[k]);
      e.rows.push_back({names[k], interval(in.a.lo[k], in.a.hi[k]), interval(in.b.lo[k], in.b.hi[k]), num(overlap)});
      if (overlap < worst) {
        worst = overlap, e.deciding_row = k;
        e.a_lo = in.a.lo[k], e.a_hi = in.a.hi[k], e.b_lo = in.b.lo[k], e.b_hi = in.b.hi[k];
        Vec3 axis;
        axis[k] = 1;
        e.axis = axis;
      }
    }
    e.deciding = "the smallest overlap (a comparison of inputs: exact)";
    e.deciding_value = worst;
    return e;
  }
  Explanation operator()(const harness::KdopKdopInput& in) const {
    Explanation e;
    e.title = "slabs of the exact k-DOPs and of the library's fitted ones";
    e.columns = {"direction", "A exact", "B exact", "overlap exact", "A fitted", "B fitted"};
    bool finite_points = !in.a.empty() && !in.b.empty();
    for (const auto* set : {&in.a, &in.b}) {
      for (const Vec3& p : *set) finite_points &= finite(p);
    }
    if (!finite_points || !is_supported_kdop(in.k)) return e;
    const auto slabs = exact_kdop_slabs(in);
    const auto dirs = kdop_directions(in.k);
    // The library's fitted slabs, through a runtime dispatch on k.
    std::vector<double> alo, ahi, blo, bhi;
    const auto fitted = [&](auto dop_a, auto dop_b) {
      alo.assign(dop_a.lo.begin(), dop_a.lo.end()), ahi.assign(dop_a.hi.begin(), dop_a.hi.end());
      blo.assign(dop_b.lo.begin(), dop_b.lo.end()), bhi.assign(dop_b.hi.begin(), dop_b.hi.end());
    };
    switch (in.k) {
      case 6: fitted(fit_kdop<6>(in.a), fit_kdop<6>(in.b)); break;
      case 14: fitted(fit_kdop<14>(in.a), fit_kdop<14>(in.b)); break;
      case 16: fitted(fit_kdop<16>(in.a), fit_kdop<16>(in.b)); break;
      case 18: fitted(fit_kdop<18>(in.a), fit_kdop<18>(in.b)); break;
      case 24: fitted(fit_kdop<24>(in.a), fit_kdop<24>(in.b)); break;
      default: fitted(fit_kdop<26>(in.a), fit_kdop<26>(in.b));
    }
    double worst = INFINITY;
    for (std::size_t i = 0; i < slabs.size(); ++i) {
      const ExactSlab& s = slabs[i];
      const Vec3 d{static_cast<double>(dirs[i].x), static_cast<double>(dirs[i].y), static_cast<double>(dirs[i].z)};
      e.rows.push_back({vec(d), interval(to_double(s.a_lo), to_double(s.a_hi)), interval(to_double(s.b_lo), to_double(s.b_hi)),
                        num(s.overlap), interval(alo[i], ahi[i]), interval(blo[i], bhi[i])});
      const double m = to_double(s.overlap) / s.length;
      if (m < worst) {
        worst = m, e.deciding_row = static_cast<int>(i);
        e.axis = d;
        e.a_lo = to_double(s.a_lo), e.a_hi = to_double(s.a_hi), e.b_lo = to_double(s.b_lo), e.b_hi = to_double(s.b_hi);
        e.deciding_value = to_double(s.overlap);
        e.deciding_ulps = in_ulps(e.deciding_value, std::max({std::fabs(e.a_lo), std::fabs(e.a_hi), std::fabs(e.b_lo),
                                                              std::fabs(e.b_hi)}));
      }
    }
    e.deciding = "the smallest overlap over the slabs (exact k-DOPs)";
    return e;
  }
  Explanation operator()(const harness::MeshMeshInput& in) const { return meshes(in.meshes); }
  Explanation operator()(const harness::MeshMeshFirstInput& in) const { return meshes(in.meshes); }
  // The pair of triangles nearest the boundary, explained as a tri_tri query.
  static Explanation meshes(const harness::MeshPair& m) {
    const harness::ExactVerdict v = judge_meshes(m);
    const harness::PairMargin* nearest = nullptr;
    for (const harness::PairMargin& p : v.pair_margins) {
      if (nearest == nullptr || std::fabs(p.margin) < std::fabs(nearest->margin)) nearest = &p;
    }
    if (nearest == nullptr) {
      Explanation e;
      e.title = "no pair near contact";
      e.deciding = "every pair's bounding boxes are apart by more than 2^" + std::to_string(std::ilogb(kNearMargin)) + " of the scale";
      e.deciding_value = v.unlisted_margin;
      return e;
    }
    const auto [a, b] = placed_triangles(m, nearest->pair);
    Explanation e = explain_polytopes(a, b);
    const std::string pair = "(" + std::to_string(nearest->pair.first) + ", " + std::to_string(nearest->pair.second) + ")";
    e.title = "pair " + pair + ", the nearest to contact: " + e.title;
    e.facts.insert(e.facts.begin(), {{"colliding pairs", std::to_string(v.answer.pairs.size())},
                                     {"pairs near contact", std::to_string(v.pair_margins.size())},
                                     {"explained pair", pair}});
    return e;
  }
  // Per frame: the boxes present, the overlapping pairs, and the pair nearest to touching.
  Explanation operator()(const harness::BroadphaseInput& in) const {
    const harness::ExactVerdict v = judge(in);
    Explanation e;
    e.title = "boxes per frame (closed-box overlap by comparisons of the bounds)";
    if (v.contract != harness::Contract::in) {
      e.deciding = v.note;
      return e;
    }
    e.columns = {"frame", "boxes", "overlapping pairs", "pairs"};
    for (std::size_t f = 0; f < in.frames.size(); ++f) {
      std::size_t present = 0;
      for (const auto& box : in.frames[f]) present += box.has_value();
      std::string listed;
      for (std::size_t i = 0; i < v.answer.frames[f].size() && i < 8; ++i) {
        const auto& [a, b] = v.answer.frames[f][i];
        listed.append("(").append(std::to_string(a)).append(", ").append(std::to_string(b)).append(") ");
      }
      if (v.answer.frames[f].size() > 8) listed.append("...");
      e.rows.push_back({std::to_string(f), std::to_string(present), std::to_string(v.answer.frames[f].size()), listed});
    }
    e.deciding = "the pair nearest to touching, over all frames (overlap > 0, gap < 0, relative to the scale)";
    e.deciding_value = v.margin;
    return e;
  }
  // The faces near the ray, each with its exact first point and its margin.
  Explanation operator()(const harness::RayMeshInput& in) const {
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
  // Per candidate axis: the projected centres' offset p + t s against the radii r, and the
  // times at which the projections overlap.
  Explanation operator()(const harness::MovingObbInput& in) const {
    const harness::ExactVerdict v = judge(in);
    Explanation e;
    e.title = "moving separating axes: |p + t s| <= r";
    if (v.contract != harness::Contract::in) {
      e.deciding = v.note;
      return e;
    }
    e.columns = {"axis", "p", "s", "r", "times"};
    const std::vector<MovingAxis> axes = moving_axes(in.a, in.b);
    for (const MovingAxis& m : axes) {
      ExactWindow w;
      w.restrict(m.p, m.s, m.r);
      e.rows.push_back({m.axis.name, num(m.p), num(m.s), num(m.r), w.hit() ? interval(to_double(w.first), to_double(w.last)) : "never"});
    }
    const ExactWindow window = exact_sweep(axes);
    e.facts.push_back({"window", window.hit() ? interval(to_double(window.first), to_double(window.last)) : "empty"});
    if (v.answer.hit) {
      e.facts.push_back({"t_first allowed", interval(v.param_ranges[0].first, v.param_ranges[0].second)});
      e.facts.push_back({"t_last allowed", interval(v.param_ranges[1].first, v.param_ranges[1].second)});
    }
    e.deciding = v.answer.hit ? "overlap halfway through the window, relative to the scale"
                              : "the closest approach: minus the largest gap over the axes, relative to the scale";
    e.deciding_value = v.margin;
    return e;
  }
  template <class In>
  Explanation operator()(const In& in) const {
    const auto shapes = polytopes_of(harness::Input{in});
    return explain_polytopes(shapes->first, shapes->second);
  }
};

}  // namespace

harness::Explanation ExactRationalReference::explain(const harness::Input& input) const {
  const harness::ExactVerdict v = judge(input);
  if (v.contract != harness::Contract::in) {
    harness::Explanation e;
    e.title = "outside the library's domain";
    e.facts = {{"contract", v.contract == harness::Contract::documented ? "documented answer" : "unspecified answer"},
               {"why", v.note}};
    e.deciding = v.note;
    return e;
  }
  return std::visit(Explain{}, input);
}

}  // namespace cc::exact
