// What the kinds' explanations share (explain.h): numbers as text, and the explanation of two
// convex polytopes by their separating-axis candidates, and of two meshes by the pair of
// triangles nearest to contact.
#include "oracle/exact/explain.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "oracle/exact/domain.h"
#include "oracle/exact/exact_meshes.h"

namespace cc::exact {

using harness::Explanation;

namespace {

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

}  // namespace

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

double in_ulps(double value, double magnitude) {
  const double m = std::fabs(magnitude);
  if (m == 0 || !std::isfinite(m)) return 0;
  const double ulp = std::nextafter(m, INFINITY) - m;
  return value / ulp;
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

// The pair of triangles nearest the boundary, explained as two triangles.
Explanation explain_meshes(const harness::MeshPair& m) {
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

}  // namespace cc::exact
