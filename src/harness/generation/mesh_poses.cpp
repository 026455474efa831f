#include "harness/generation/mesh_poses.h"

#include <cmath>

#include "harness/model/mesh_collide.h"
#include "harness/generation/touch.h"

namespace cc::harness {
namespace {

constexpr double kPi = 3.141592653589793;

double unit(Choices& c) { return static_cast<double>(c.draw(std::uint64_t{1} << 53)) * 0x1p-53; }
double between(Choices& c, double lo, double hi) { return lo + (hi - lo) * unit(c); }

// The furthest any vertex of the mesh is from its pose's origin, in norm1 (a bound on its
// extent in any direction).
double reach(const Mesh& m) {
  double r = 0;
  for (const Vec3& v : m.vertices) r = std::max(r, norm1(v));
  return r;
}

}  // namespace

Mat3 fcl_style_rotation(Choices& c) {
  const double a = between(c, -kPi, kPi), b = between(c, -kPi, kPi), g = between(c, -kPi, kPi);
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b), cg = std::cos(g),
               sg = std::sin(g);
  Mat3 m;
  m(0, 0) = cb * cg, m(0, 1) = sa * sb * cg - ca * sg, m(0, 2) = ca * sb * cg + sa * sg;
  m(1, 0) = cb * sg, m(1, 1) = sa * sb * sg + ca * cg, m(1, 2) = ca * sb * sg - sa * cg;
  m(2, 0) = -sb, m(2, 1) = sa * cb, m(2, 2) = ca * cb;
  return m;
}

RigidTransform fcl_style_pose(Choices& c) {
  RigidTransform t;
  t.rotation = fcl_style_rotation(c);
  t.translation = {between(c, -3000, 3000), between(c, -3000, 3000), between(c, 0, 3000)};
  return t;
}

void bisect_to_contact(MeshPair& m, Choices& c) {
  touch_at_vertices(m, c);
  const Vec3 start = m.pose_b.translation;
  // Moved this far, b's origin is at least reach_a + reach_b + 1 from a's (the vertices met, each
  // within its mesh's reach of its origin): the meshes are apart.
  const double far = 2 * (reach(*m.a.mesh) + reach(*m.b.mesh)) + 1;
  // A generic direction, or one in a coordinate plane or along an axis (each component 0 a
  // quarter of the time; none at all: along x).
  Vec3 direction;
  for (int k = 0; k < 3; ++k) direction[k] = c.chance(25) ? 0.0 : between(c, -1, 1);
  if (norm1(direction) == 0) direction = {1, 0, 0};
  direction = (1 / std::sqrt(dot(direction, direction))) * direction;
  const auto collides_at = [&](double s) {
    MeshPair trial = m;
    trial.pose_b.translation = start + s * direction;
    return !library_collide(trial, CollisionMode::first_hit).pairs.empty();
  };
  double in = 0, out = far;
  if (!collides_at(in)) return;  // nothing to bisect (no pair at the start)
  for (int step = 0; step < 64; ++step) {
    const double mid = 0.5 * (in + out);
    if (mid == in || mid == out) break;
    (collides_at(mid) ? in : out) = mid;
  }
  m.pose_b.translation = start + (c.chance(50) ? in : out) * direction;
}

}  // namespace cc::harness
