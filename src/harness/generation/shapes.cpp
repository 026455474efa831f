// Generators for aabb_aabb, kdop_kdop and obb_obb, and the box helpers the others share.
#include <cmath>
#include <tuple>
#include <utility>

#include "collide/kdop.h"
#include "harness/generation/shapes.h"
#include "harness/generation/rotation.h"
#include "harness/generation/touch.h"

namespace cc::harness::detail {
namespace {

// Places [lo, hi] on one axis relative to [a_lo, a_hi]: touching above or below, overlapping,
// or (with `nudged`) a few ULPs away from touching.
std::pair<double, double> place_on_axis(ValueSource& v, double a_lo, double a_hi, bool touch, bool nudged) {
  const double len = v.length();
  if (touch) {
    if (v.choices().chance(50)) {
      const double lo = nudged ? v.nudge(a_hi) : a_hi;
      return {lo, lo + len};
    }
    const double hi = nudged ? v.nudge(a_lo) : a_lo;
    return {hi - len, hi};
  }
  const double anchors[] = {a_lo, a_hi, 0.5 * (a_lo + a_hi)};
  const double lo = anchors[v.choices().draw(3)] - (v.choices().chance(50) ? 0.0 : len);
  return {lo, lo + v.length()};
}

}  // namespace

Aabb draw_aabb(ValueSource& v, const GenerateOptions& options) {
  Aabb b;
  b.lo = v.point();
  for (int k = 0; k < 3; ++k) b.hi[k] = b.lo[k] + v.length();
  if (options.out_of_contract && v.choices().chance(15)) {
    const int k = static_cast<int>(v.choices().draw(3));
    std::swap(b.lo[k], b.hi[k]);
    if (b.lo[k] == b.hi[k]) b.lo[k] = std::nextafter(b.hi[k], INFINITY);
  }
  return b;
}

Vec3 draw_boundary_point(ValueSource& v, const Aabb& box) {
  Vec3 p;
  const auto on_bounds = 1 + v.choices().draw(3);  // 3: a corner, 2: an edge, 1: a face
  const auto first = v.choices().draw(3);
  for (std::uint64_t i = 0; i < 3; ++i) {
    const int k = static_cast<int>((first + i) % 3);
    if (i < on_bounds) {
      p[k] = v.choices().chance(50) ? box.lo[k] : box.hi[k];
    } else {
      p[k] = 0.5 * (box.lo[k] + box.hi[k]);
    }
  }
  return p;
}

AabbAabbInput generate_aabb_aabb(ValueSource& v, const GenerateOptions& options) {
  AabbAabbInput in;
  in.a = draw_aabb(v, options);
  switch (v.choices().draw(5)) {
    case 0: in.b = draw_aabb(v, options); break;
    case 1:
    case 2: {  // touching on 1 to 3 axes (face, edge, corner), exactly or a few ULPs off
      const bool nudged = v.choices().chance(30);
      const auto touching = 1 + v.choices().draw(3);
      const auto first = v.choices().draw(3);
      for (std::uint64_t i = 0; i < 3; ++i) {
        const int k = static_cast<int>((first + i) % 3);
        std::tie(in.b.lo[k], in.b.hi[k]) = place_on_axis(v, in.a.lo[k], in.a.hi[k], i < touching, nudged);
      }
      break;
    }
    case 3: in.b = in.a; break;
    default: {  // a point of A's boundary, or a point nudged off it
      const Vec3 p = draw_boundary_point(v, in.a);
      in.b = {p, p};
      if (v.choices().chance(50)) {
        const int k = static_cast<int>(v.choices().draw(3));
        in.b.lo[k] = in.b.hi[k] = v.nudge(p[k]);
      }
    }
  }
  if (v.choices().chance(50)) std::swap(in.a, in.b);
  return in;
}

namespace {

constexpr int kKs[] = {18, 6, 14, 16, 24, 26};

// Two point sets at an exact margin in the regimes of fit_kdop's bound: clusters far from the
// origin compared with their spread (where 2- and 3-term projections cancel), spreads up to 2^40
// apart; b slid from a's centre along a slab's direction or any.
KdopKdopInput kdops_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  KdopKdopInput in;
  in.k = kKs[c.draw(6)];
  const double size = draw_size(v);
  const Vec3 center = v.point() + draw_far_offset(v, size);
  const auto cluster = [&](double spread) {
    std::vector<Vec3> points;
    const auto n = 1 + c.draw(6);
    for (std::uint64_t i = 0; i < n; ++i) points.push_back(center + std::ldexp(spread, -static_cast<int>(c.draw(41))) * draw_direction(v));
    return points;
  };
  in.a = cluster(size);
  const std::vector<Vec3> b = cluster(std::ldexp(size, v.small_int(20)));
  const auto dirs = kdop_directions(in.k);
  Vec3 w = draw_direction(v);
  if (c.chance(60)) {
    const KdopDirection d = dirs[c.draw(dirs.size())];
    w = {static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z)};
  }
  double reach = 0;
  for (const Vec3& p : in.a) reach = std::max(reach, std::fabs(dot(p - center, w)));
  for (const Vec3& p : b) reach = std::max(reach, std::fabs(dot(p - center, w)));
  const auto placed = [&in, &b, &w](double s) {
    KdopKdopInput out = in;
    for (const Vec3& p : b) out.b.push_back(p + s * w);
    return out;
  };
  const double contact = 2 * reach / dot(w, w);
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, 2 * contact + 1 / std::sqrt(dot(w, w)),
                            draw_margin_target(c), options, contact);
  KdopKdopInput out = placed(s);
  shuffle(c, out.a);
  shuffle(c, out.b);
  return out;
}

}  // namespace

KdopKdopInput generate_kdop_kdop(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return kdops_at_the_bound(v, options);
  KdopKdopInput in;
  in.k = kKs[v.choices().draw(6)];
  const Vec3 center = v.point();
  const auto cluster = [&](std::vector<Vec3>& points) {
    const auto n = 1 + v.choices().draw(5);
    for (std::uint64_t i = 0; i < n; ++i) points.push_back(v.choices().chance(40) ? center + v.point() : v.point());
  };
  cluster(in.a);
  switch (v.choices().draw(4)) {
    case 0: cluster(in.b); break;
    case 1: {  // share a point of A, or repeat A
      in.b.push_back(in.a[v.choices().draw(in.a.size())]);
      if (v.choices().chance(50)) in.b = in.a;
      break;
    }
    default:  // B shifted so that its k-DOP touches A's on one slab (exact when the sums are)
      cluster(in.b);
      shift_to_touch(in, v, v.choices().chance(25));
  }
  shuffle(v.choices(), in.a);
  shuffle(v.choices(), in.b);
  return in;
}

Obb draw_obb(ValueSource& v, const GenerateOptions& options) {
  Obb b;
  b.center = v.point();
  b.half = {v.length(), v.length(), v.length()};
  b.axes = draw_rotation(v);
  if (options.out_of_contract) {
    if (v.choices().chance(10)) b.axes = draw_non_orthonormal(v);
    if (v.choices().chance(10)) b.half[static_cast<int>(v.choices().draw(3))] = -v.length() - 1;
  }
  return b;
}

ObbObbInput obb_pair_in_regime(ValueSource& v) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  ObbObbInput in;
  in.a.center = v.point() + draw_far_offset(v, size);
  in.a.half = draw_aspect_extents(v, size);
  in.a.axes = draw_rotation(v);
  in.b.center = in.a.center;
  in.b.half = draw_aspect_extents(v, c.chance(50) ? size : std::ldexp(size, v.small_int(40)));
  in.b.axes = c.chance(40) ? nearly_parallel(v, in.a.axes) : draw_rotation(v);
  if (c.chance(50)) in.a.axes = perturb_to_tolerance(v, in.a.axes);
  if (c.chance(50)) in.b.axes = perturb_to_tolerance(v, in.b.axes);
  return in;
}

Vec3 slide_direction(ValueSource& v, const Obb& a, const Obb& b) {
  Choices& c = v.choices();
  Vec3 w;
  switch (c.draw(4)) {
    case 0: w = a.axes.col[c.draw(3)]; break;                                 // face to face
    case 1: w = b.axes.col[c.draw(3)]; break;
    case 2: w = cross(a.axes.col[c.draw(3)], b.axes.col[c.draw(3)]); break;  // edge to edge
    default: w = draw_direction(v);
  }
  if (!(max_abs(w) > 0x1p-60)) w = draw_direction(v);
  return c.chance(50) ? -1.0 * w : w;
}

double reach_along(const Obb& box, const Vec3& w) {
  double r = 0;
  for (int k = 0; k < 3; ++k) r += box.half[k] * std::fabs(dot(box.axes.col[k], w));
  return r;
}

namespace {

// Two boxes at an exact margin of the decision, in the regimes of test_obb_obb's bound: b slid
// from a's centre along a face normal, an edge-edge axis or any direction.
ObbObbInput obb_pair_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  const ObbObbInput in = obb_pair_in_regime(v);
  const Vec3 w = slide_direction(v, in.a, in.b);
  const Obb &a = in.a, &b = in.b;
  const auto placed = [&a, &b, &w](double s) -> ObbObbInput {
    Obb moved = b;
    moved.center = a.center + s * w;
    return {a, moved};
  };
  const double contact = (reach_along(a, w) + reach_along(b, w)) / dot(w, w);  // along a separating w
  const double apart = 2 * contact + std::sqrt(max_abs(a.half) + max_abs(b.half)) + 1 / std::sqrt(dot(w, w));
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, apart,
                            draw_margin_target(v.choices()), options, contact);
  return placed(s);
}

}  // namespace

ObbObbInput generate_obb_obb(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return obb_pair_at_the_bound(v, options);
  ObbObbInput in;
  in.a = draw_obb(v, options);
  in.b = draw_obb(v, options);
  const auto mode = v.choices().draw(5);
  if (mode == 1 || mode == 3) in.b.axes = draw_rotation_near(v, in.a.axes);  // nearly parallel edges
  if (mode >= 1 && mode <= 3) {
    // B against a face of A: exact for exactly orthonormal axes and simple values, else within ULPs.
    place_against_face(in, v, mode == 2);
  } else if (mode == 4) {
    in.b.center = in.a.center;
  }
  return in;
}

}  // namespace cc::harness::detail
