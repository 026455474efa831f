#include "collide/separating_axis.h"

#include <vector>

namespace cc::sat {

TriangleSet::TriangleSet(const Triangle& tri)
    : t(tri), magnitude_(std::max({max_abs(tri.v[0]), max_abs(tri.v[1]), max_abs(tri.v[2])})) {}

Interval TriangleSet::project(const Vec3& axis) const {
  const double p0 = dot(axis, t.v[0]), p1 = dot(axis, t.v[1]), p2 = dot(axis, t.v[2]);
  return {std::min({p0, p1, p2}), std::max({p0, p1, p2})};
}

Vec3 TriangleSet::centroid() const {
  const auto mean = [this](int k) { return fp::sum3(t.v[0][k], t.v[1][k], t.v[2][k]) / 3; };
  return {mean(0), mean(1), mean(2)};
}

BoxSet::BoxSet(const Aabb& b) : box(b), magnitude_(std::max(max_abs(b.lo), max_abs(b.hi))) {}

Interval BoxSet::project(const Vec3& axis) const {
  double low[3], high[3];
  for (int k = 0; k < 3; ++k) {
    const double a = axis[k] * box.lo[k], b = axis[k] * box.hi[k];
    low[k] = std::min(a, b);
    high[k] = std::max(a, b);
  }
  return {fp::sum3(low[0], low[1], low[2]), fp::sum3(high[0], high[1], high[2])};
}

Vec3 BoxSet::centroid() const { return 0.5 * (box.lo + box.hi); }

namespace {

// The record of a gap: the sets as they were projected.
bounds::SatAxis sat_axis(const Vec3& axis, const TriangleSet& a, const TriangleSet& b, double gap,
                         const bounds::SatBound& bound) {
  return {axis, false, a.t, {}, b.t, gap, bound};
}
bounds::SatAxis sat_axis(const Vec3& axis, const BoxSet& a, const TriangleSet& b, double gap,
                         const bounds::SatBound& bound) {
  return {axis, true, {}, a.box, b.t, gap, bound};
}

}  // namespace

template <class A, class B, class Records>
bool separates(const Vec3& axis, const A& a, const B& b, double perturbation, Records& records) {
  const Interval pa = a.project(axis), pb = b.project(axis);
  const double gap = std::max(pb.lo - pa.hi, pa.lo - pb.hi);
  const bounds::SatBound bound{norm1(axis), a.magnitude(), b.magnitude(), perturbation};
  records.add(sat_axis(axis, a, b, gap, bound));
  return gap > bound.total();
}

template <class A, class B, class Records>
bool separated_by_degenerate_axes(const A& a, const B& b, std::span<const Vec3> generators,
                                  double perturbation, Records& records) {
  std::vector<Vec3> normals;
  for (std::size_t i = 0; i < generators.size(); ++i) {
    for (std::size_t j = i + 1; j < generators.size(); ++j) {
      const Vec3 c = unit_scaled(cross(generators[i], generators[j]));
      if (c == Vec3{}) continue;
      if (separates(c, a, b, perturbation, records)) return true;
      normals.push_back(c);
    }
  }
  for (const Vec3& c : normals) {  // in-plane normals of a flat Minkowski difference
    for (const Vec3& g : generators) {
      if (separates(unit_scaled(cross(c, g)), a, b, perturbation, records)) return true;
    }
  }
  const Vec3 o = unit_scaled(b.centroid() - a.centroid());
  for (const Vec3& g : generators) {  // a collinear difference: along and across its line
    if (separates(g, a, b, perturbation, records)) return true;
    if (separates(unit_scaled(cross(g, unit_scaled(cross(g, o)))), a, b, perturbation, records)) return true;
  }
  return separates(o, a, b, perturbation, records);  // two points
}

#define CC_INSTANTIATE(A, R)                                                  \
  template bool separates(const Vec3&, const A&, const TriangleSet&, double, R&); \
  template bool separated_by_degenerate_axes(const A&, const TriangleSet&, std::span<const Vec3>, double, R&);
CC_INSTANTIATE(TriangleSet, bounds::NoRecords)
CC_INSTANTIATE(TriangleSet, bounds::RecordsRef)
CC_INSTANTIATE(BoxSet, bounds::NoRecords)
CC_INSTANTIATE(BoxSet, bounds::RecordsRef)
#undef CC_INSTANTIATE

}  // namespace cc::sat
