#include "collide/triangle_triangle.h"

#include <type_traits>

#include "collide/independence_bound.h"
#include "collide/separating_axis.h"
#include "collide/simd_lanes.h"

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

// The certified test: edges scaled to unit magnitude (short, even subnormal, edges still give
// axes whose projections do not underflow), sums by fp::sum3, and the axes of coplanar and
// degenerate configurations when the 11 usual ones cannot be complete. (Not inlined into the
// fast test's kernels: it is their rare fallback.)
template <class Records>
[[gnu::noinline]] bool certified(const Triangle& a, const Triangle& b, Records& records) {
  const sat::TriangleSet sa{a}, sb{b};
  const Vec3 ea[3] = {unit_scaled(a.v[1] - a.v[0]), unit_scaled(a.v[2] - a.v[1]), unit_scaled(a.v[0] - a.v[2])};
  const Vec3 eb[3] = {unit_scaled(b.v[1] - b.v[0]), unit_scaled(b.v[2] - b.v[1]), unit_scaled(b.v[0] - b.v[2])};
  const Vec3 na = cross(ea[0], ea[1]), nb = cross(eb[0], eb[1]);
  if (sat::separates(na, sa, sb, 0, records) || sat::separates(nb, sa, sb, 0, records)) return false;
  // The normal again from the other pairs of edges: of a sliver, scaling its long edges down can
  // flush a subnormal component to 0 and leave e0 x e1 zero, where a pair with the short edge
  // (scaled up exactly) still gives the normal.
  for (int k = 1; k < 3; ++k) {
    if (sat::separates(cross(ea[k], ea[(k + 1) % 3]), sa, sb, 0, records) ||
        sat::separates(cross(eb[k], eb[(k + 1) % 3]), sa, sb, 0, records)) {
      return false;
    }
  }
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

// The edges (lane k: edge k, by coordinate) whose largest component lies in [2^-330, 2^330]:
// their cross products neither underflow nor overflow (nor lose their direction to subnormal
// rounding), and a separation 2^-44 M (in the margin's units) on an axis built from them exceeds
// the subnormal slack. Zero edges and infinities fail. (An edge with NaN may pass: every
// comparison of the test fails on it, and the hit path's contract check answers false.)
template <class T>
unsigned well_resolved(const T& x, const T& y, const T& z) {
  const T m = max(max(abs(x), abs(y)), abs(z));
  return T::bits((T::broadcast(0x1p-330) <= m) & (m <= T::broadcast(0x1p330)));
}

// Three candidate axes (lane k: the axis (cx, cy, cz)[k]) tried at once: each separates when the
// gap between the projections of a and b exceeds bounds::SatBound, with `per_unit` its
// projection_per_unit(). Returns the lanes that separate; records each lane's gap.
template <class T, class Records>
unsigned separating(const T& cx, const T& cy, const T& cz, const Triangle& a, const Triangle& b, const T& per_unit,
                    double magnitude_a, double magnitude_b, int lanes, Records& records) {
  const auto project = [&](const Vec3& v) {
    return T::broadcast_from(&v.x) * cx + T::broadcast_from(&v.y) * cy + T::broadcast_from(&v.z) * cz;
  };
  const T a0 = project(a.v[0]), a1 = project(a.v[1]), a2 = project(a.v[2]);
  const T b0 = project(b.v[0]), b1 = project(b.v[1]), b2 = project(b.v[2]);
  const T gap = max(min(min(b0, b1), b2) - max(max(a0, a1), a2), min(min(a0, a1), a2) - max(max(b0, b1), b2));
  const T norm1 = abs(cx) + abs(cy) + abs(cz);
  const T bound = norm1 * per_unit + T::broadcast(fp::subnormal_slack);
  if constexpr (!std::is_same_v<Records, bounds::NoRecords>) {
    double x[4], y[4], z[4], g[4], n[4];
    cx.store(x), cy.store(y), cz.store(z), gap.store(g), norm1.store(n);
    for (int k = 0; k < lanes; ++k) {
      records.add(bounds::SatAxis{{x[k], y[k], z[k]}, false, a, {}, b, g[k], {n[k], magnitude_a, magnitude_b, 0}});
    }
  }
  return T::bits(gap > bound) & ((1u << lanes) - 1);
}

// The largest absolute coordinate of a triangle, in every lane.
template <class T>
T magnitude(const Triangle& t) {
  const T m = max(max(abs(T::load(t.v[0])), abs(T::load(t.v[1]))), abs(T::load(t.v[2])));
  return max(max(m, m.rotate1()), m.rotate2());
}

// The fast test: the same 11 axes as the certified test, from the edges as given (the scaled
// ones are these times powers of two), plain left-to-right sums, three axes at a time. Each axis
// is certified on its own bound as there, so a separation found is exactly right, and the
// answer is right within the same band; it can differ from the certified test's only where both
// are. Before a hit, the edges must be well resolved and certainly span space (the 11 axes are
// then complete); otherwise the certified test decides. Symmetric in a and b bit for bit
// (swapping negates every edge axis exactly, and the gap and bound are the same for a negated
// axis), and under flipping an axis.
template <class T, class Records>
bool test(const Triangle& a, const Triangle& b, Records& records) {
  // (Each quantity is computed where it is first needed: most pairs apart are apart along a
  // normal, and the rest of the test waits for that.)
  const double magnitude_a = magnitude<T>(a).lane0(), magnitude_b = magnitude<T>(b).lane0();
  const T per_unit = T::broadcast(bounds::SatBound{0, magnitude_a, magnitude_b, 0}.projection_per_unit());
  const auto edge = [](const Triangle& t, int k) { return t.v[(k + 1) % 3] - t.v[k]; };

  // The two normals (lane 2 repeats a's).
  const Vec3 na = cross(edge(a, 0), edge(a, 1)), nb = cross(edge(b, 0), edge(b, 1));
  if (separating(T::set(na.x, nb.x, na.x), T::set(na.y, nb.y, na.y), T::set(na.z, nb.z, na.z), a, b, per_unit,
                 magnitude_a, magnitude_b, 2, records) != 0) {
    return false;
  }
  // a's edge i crossed with each of b's edges (lane j): b's edges by coordinate, b_{j+1} - b_j.
  T bx, by, bz;
  T::transpose(b.v.data(), bx, by, bz);
  const T fx = bx.rotate1() - bx, fy = by.rotate1() - by, fz = bz.rotate1() - bz;
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = edge(a, i);
    const T ex = T::broadcast(e.x), ey = T::broadcast(e.y), ez = T::broadcast(e.z);
    if (separating(ey * fz - ez * fy, ez * fx - ex * fz, ex * fy - ey * fx, a, b, per_unit, magnitude_a, magnitude_b, 3,
                   records) != 0) {
      return false;
    }
  }
  T ax, ay, az;
  T::transpose(a.v.data(), ax, ay, az);
  const T ex = ax.rotate1() - ax, ey = ay.rotate1() - ay, ez = az.rotate1() - az;
  if ((well_resolved(ex, ey, ez) & well_resolved(fx, fy, fz)) != 7) return certified(a, b, records);
  // The 11 axes are complete when the edges span space: an edge of one triangle certainly leaves
  // the other's plane (bounds::IndependenceBound). det(ea0, ea1, eb_k) = na . eb_k in lane k,
  // det(eb0, eb1, ea_k) = nb . ea_k.
  const T det_a = T::broadcast(na.x) * fx + T::broadcast(na.y) * fy + T::broadcast(na.z) * fz;
  const T det_b = T::broadcast(nb.x) * ex + T::broadcast(nb.y) * ey + T::broadcast(nb.z) * ez;
  const T norm_eb = abs(fx) + abs(fy) + abs(fz), norm_ea = abs(ex) + abs(ey) + abs(ez);
  // Lane k's bound is bounds::IndependenceBound{|u|_1, |v|_1, |w_k|_1}.total(), bit for bit (its
  // rounding term with |w|_1 = 1 is the product of the first two factors, times 1 exactly), the
  // 1-norms those of the lanes.
  double n_ea[4], n_eb[4];
  norm_ea.store(n_ea), norm_eb.store(n_eb);
  const bounds::IndependenceBound plane_a{n_ea[0], n_ea[1], 1}, plane_b{n_eb[0], n_eb[1], 1};
  const T slack = T::broadcast(fp::subnormal_slack);
  const T bound_a = T::broadcast(plane_a.rounding()) * norm_eb + slack, bound_b = T::broadcast(plane_b.rounding()) * norm_ea + slack;
  if constexpr (!std::is_same_v<Records, bounds::NoRecords>) {
    const Vec3 ea[3] = {edge(a, 0), edge(a, 1), edge(a, 2)}, eb[3] = {edge(b, 0), edge(b, 1), edge(b, 2)};
    double da[4], db[4];
    det_a.store(da), det_b.store(db);
    for (int k = 0; k < 3; ++k) {
      records.add(bounds::Independence{na, ea[0], ea[1], eb[k], da[k], {plane_a.u_norm1, plane_a.v_norm1, n_eb[k]}});
      records.add(bounds::Independence{nb, eb[0], eb[1], ea[k], db[k], {plane_b.u_norm1, plane_b.v_norm1, n_ea[k]}});
    }
  }
  if (T::bits((abs(det_a) > bound_a) | (abs(det_b) > bound_b)) == 0) return certified(a, b, records);
  return finite(a) && finite(b);  // on the hit path only: non-finite input gives false
}

[[gnu::flatten]] bool test_scalar(const Triangle& a, const Triangle& b) {
  bounds::NoRecords none;
  return test<simd::Triple<simd::Scalar>>(a, b, none);
}

[[gnu::target("avx2"), gnu::flatten, gnu::optimize("no-tree-slp-vectorize")]] bool test_avx2(const Triangle& a, const Triangle& b) {
  bounds::NoRecords none;
  return test<simd::Triple<simd::Avx2>>(a, b, none);
}

// The AVX2 triples again, compiled for AVX-512 processors, which lend them 32 vector registers.
[[gnu::target("avx512f,avx512dq,avx512vl"), gnu::flatten, gnu::optimize("no-tree-slp-vectorize")]] bool test_avx512(const Triangle& a, const Triangle& b) {
  bounds::NoRecords none;
  return test<simd::Triple<simd::Avx2>>(a, b, none);
}

}  // namespace

bool test_triangle_triangle(const Triangle& a, const Triangle& b) {
  switch (simd::selected()) {
    case simd::Kernel::scalar: return test_scalar(a, b);
    case simd::Kernel::avx2: return test_avx2(a, b);
    case simd::Kernel::avx512: return test_avx512(a, b);
  }
  return test_scalar(a, b);
}

bool test_triangle_triangle(const Triangle& a, const Triangle& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return test<simd::Triple<simd::Scalar>>(a, b, into);
}

}  // namespace cc
