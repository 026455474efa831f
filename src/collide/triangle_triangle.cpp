#include "collide/triangle_triangle.h"

#include "collide/separating_axis.h"

namespace cc {
namespace {

// True when det(u, v, w) is nonzero beyond its rounding error (bounds::IndependenceBound).
template <class Records>
bool certainly_independent(const Vec3& u_cross_v, const Vec3& u, const Vec3& v, const Vec3& w, Records& records) {
  const bounds::IndependenceBound bound{norm1(u), norm1(v), norm1(w)};
  const double det = dot(u_cross_v, w);
  records.add(bounds::Independence{u_cross_v, u, v, w, det, bound});
  return std::fabs(det) > bound.total();
}

template <class Records>
bool test(const Triangle& a, const Triangle& b, Records& records) {
  const sat::TriangleSet sa{a}, sb{b};
  // Edge directions, scaled to unit magnitude so that short (even subnormal) edges give axes
  // whose projections do not underflow.
  const Vec3 ea[3] = {unit_scaled(a.v[1] - a.v[0]), unit_scaled(a.v[2] - a.v[1]), unit_scaled(a.v[0] - a.v[2])};
  const Vec3 eb[3] = {unit_scaled(b.v[1] - b.v[0]), unit_scaled(b.v[2] - b.v[1]), unit_scaled(b.v[0] - b.v[2])};
  const Vec3 na = cross(ea[0], ea[1]), nb = cross(eb[0], eb[1]);
  if (sat::separates(na, sa, sb, 0, records) || sat::separates(nb, sa, sb, 0, records)) return false;
  for (const Vec3& e : ea) {
    for (const Vec3& f : eb) {
      if (sat::separates(cross(e, f), sa, sb, 0, records)) return false;
    }
  }
  // The 11 axes are complete when the edges span space: some edge of one triangle leaves the
  // plane of the other. Otherwise (coplanar, or both degenerate) add the remaining axes.
  bool full_dimensional = false;
  for (int k = 0; k < 3 && !full_dimensional; ++k) {
    full_dimensional = certainly_independent(na, ea[0], ea[1], eb[k], records) ||
                       certainly_independent(nb, eb[0], eb[1], ea[k], records);
  }
  if (!full_dimensional) {
    const Vec3 generators[6] = {ea[0], ea[1], ea[2], eb[0], eb[1], eb[2]};
    if (sat::separated_by_degenerate_axes(sa, sb, generators, 0, records)) return false;
  }
  return finite(a) && finite(b);  // on the hit path only: non-finite input gives false
}

}  // namespace

bool test_triangle_triangle(const Triangle& a, const Triangle& b) {
  bounds::NoRecords none;
  return test(a, b, none);
}

bool test_triangle_triangle(const Triangle& a, const Triangle& b, bounds::Records& records) {
  return test(a, b, records);
}

}  // namespace cc
