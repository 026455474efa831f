#include "collide/triangle_box.h"

#include "collide/frame_change_bound.h"
#include "collide/separating_axis.h"

namespace cc {
namespace {

// The triangle and the box [box.lo, box.hi] in a common frame in which the box is axis
// aligned; the triangle's coordinates may be off by `perturbation` each.
template <class Records>
bool test_in_box_frame(const Triangle& t, const Aabb& box, double perturbation, Records& records) {
  // The box's axes: the projections of the triangle onto them are its coordinates.
  for (int k = 0; k < 3; ++k) {
    const double low = std::min({t.v[0][k], t.v[1][k], t.v[2][k]});
    const double high = std::max({t.v[0][k], t.v[1][k], t.v[2][k]});
    if (box.lo[k] - high > perturbation || low - box.hi[k] > perturbation) return false;
  }
  const sat::TriangleSet tri{t};
  const sat::BoxSet set{box};
  // Edge directions scaled to unit magnitude: short edges still give axes that do not underflow.
  const Vec3 edges[3] = {unit_scaled(t.v[1] - t.v[0]), unit_scaled(t.v[2] - t.v[1]), unit_scaled(t.v[0] - t.v[2])};
  if (sat::separates(cross(edges[0], edges[1]), set, tri, perturbation, records)) return false;
  for (const Vec3& e : edges) {  // e x x, e x y, e x z: exact components, no arithmetic
    if (sat::separates(Vec3{0, e.z, -e.y}, set, tri, perturbation, records)) return false;
    if (sat::separates(Vec3{-e.z, 0, e.x}, set, tri, perturbation, records)) return false;
    if (sat::separates(Vec3{e.y, -e.x, 0}, set, tri, perturbation, records)) return false;
  }
  // A box with positive extent on every axis makes the Minkowski difference full-dimensional,
  // and then the 13 axes are complete. Otherwise try the axes of degenerate configurations.
  if (box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z) return true;
  Vec3 generators[6];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    if (box.lo[k] < box.hi[k]) {
      Vec3 axis;
      axis[k] = 1;
      generators[n++] = axis;
    }
  }
  for (const Vec3& e : edges) generators[n++] = e;
  return !sat::separated_by_degenerate_axes(set, tri, std::span<const Vec3>(generators, n), perturbation, records);
}

template <class Records>
bool test_aabb(const Triangle& t, const Aabb& box, Records& records) {
  if (!test_in_box_frame(t, box, 0, records)) return false;
  return finite(t) && finite(box.lo) && finite(box.hi) && box.lo.x <= box.hi.x && box.lo.y <= box.hi.y &&
         box.lo.z <= box.hi.z;
}

template <class Records>
bool test_obb(const Triangle& t, const Obb& box, Records& records) {
  Triangle local;
  double reach = 0;  // largest |v - center|_1
  for (int k = 0; k < 3; ++k) {
    const Vec3 offset = t.v[k] - box.center;
    local.v[k] = transpose_times(box.axes, offset);
    reach = std::max(reach, norm1(offset));
  }
  // The local coordinates' rounding, and the box's faces moved by the axes' deviation from
  // orthonormal (see bounds::FrameChangeBound).
  const double half_sum = fp::sum3(box.half.x, box.half.y, box.half.z);
  const bounds::FrameChangeBound bound{reach, half_sum};
  records.add(bounds::FrameChange{t, box, local, bound});
  const double perturbation = bound.total();
  if (!test_in_box_frame(local, Aabb{-box.half, box.half}, perturbation, records)) return false;
  return finite(t) && in_domain(box);
}

}  // namespace

bool test_triangle_aabb(const Triangle& t, const Aabb& box) {
  bounds::NoRecords none;
  return test_aabb(t, box, none);
}

bool test_triangle_aabb(const Triangle& t, const Aabb& box, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return test_aabb(t, box, into);
}

bool test_triangle_obb(const Triangle& t, const Obb& box) {
  bounds::NoRecords none;
  return test_obb(t, box, none);
}

bool test_triangle_obb(const Triangle& t, const Obb& box, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return test_obb(t, box, into);
}

}  // namespace cc
