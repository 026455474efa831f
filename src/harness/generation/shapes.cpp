// Boxes for the generators: axis-aligned and oriented, points of their boundary, pairs of
// oriented boxes in the regimes of the box tests' bounds.
#include "harness/generation/shapes.h"

#include <cmath>
#include <utility>

#include "harness/generation/regimes.h"
#include "harness/generation/rotation.h"

namespace cc::harness {

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

Obb draw_obb(ValueSource& v, const GenerateOptions& options) {
  Obb b;
  b.center = v.point();
  b.half = {v.length(), v.length(), v.length()};
  b.axes = draw_rotation(v);
  if (options.out_of_contract) {
    if (v.choices().chance(10)) b.axes = draw_non_orthonormal(v);
    if (v.choices().chance(10)) {
      const double negative = -v.length() - 1;  // drawn before its component
      b.half = with_one_component(b.half, negative, v.choices());
    }
  }
  return b;
}

ObbPair obb_pair_in_regime(ValueSource& v) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  ObbPair in;
  const Vec3 offset = draw_far_offset(v, size);  // drawn before the point, as always
  in.a.center = v.point() + offset;
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
    case 2: {  // edge to edge
      const auto j = c.draw(3), i = c.draw(3);  // b's axis drawn first, as always
      w = cross(a.axes.col[i], b.axes.col[j]);
      break;
    }
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

}  // namespace cc::harness
