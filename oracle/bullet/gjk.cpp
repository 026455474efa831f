#include "oracle/bullet/gjk.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "oracle/bullet/convert.h"

namespace cc::bullet_oracle {
namespace {

// What GJK reports (once, for a valid query).
struct Closest final : btDiscreteCollisionDetectorInterface::Result {
  std::optional<GjkClosest> reported;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3& normal_on_b, const btVector3& point_on_b, btScalar depth) override {
    const btVector3 point_on_a = point_on_b + normal_on_b * depth;
    reported = GjkClosest{depth, {point_on_a.x(), point_on_a.y(), point_on_a.z()}, {point_on_b.x(), point_on_b.y(), point_on_b.z()}};
  }
};

}  // namespace

std::optional<GjkClosest> gjk_closest(const btConvexShape& a, const btTransform& place_a, const btConvexShape& b,
                                      const btTransform& place_b) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver penetration;
  btGjkPairDetector gjk(&a, &b, &simplex, &penetration);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  input.m_transformA = place_a;
  input.m_transformB = place_b;
  Closest result;
  gjk.getClosestPoints(input, result, nullptr);
  return result.reported;
}

harness::Opinion distance_answer(const std::optional<GjkClosest>& c) {
  if (!c) return harness::failed("GJK reported no distance");
  harness::Answer answer = harness::Answer::of(c->distance <= 0);
  answer.params = {c->distance, c->on_a.x, c->on_a.y, c->on_a.z, c->on_b.x, c->on_b.y, c->on_b.z};
  return harness::answered(answer);
}

harness::Opinion epa_signed_distance(const Vec3& center, double radius, const btConvexShape& shape,
                                     const btTransform& place) {
  btGjkEpaSolver2::sResults results;
  const btScalar d = btGjkEpaSolver2::SignedDistance(to_bullet(center), radius, &shape, place, results);
  if (d == SIMD_INFINITY) return harness::failed("GJK and EPA reported no distance");
  harness::Answer answer = harness::Answer::of(d <= 0);
  answer.params = {d};
  return harness::answered(answer);
}

std::optional<double> gjk_distance(const btConvexShape& a, const btTransform& place_a, const btConvexShape& b,
                                   const btTransform& place_b) {
  const std::optional<GjkClosest> closest = gjk_closest(a, place_a, b, place_b);
  if (!closest) return std::nullopt;
  return closest->distance;
}

harness::Opinion gjk_triangle_box(const Triangle& tri, const Vec3& half, const Mat3& axes, const Vec3& center) {
  btTriangleShape triangle(to_bullet(tri.v[0]), to_bullet(tri.v[1]), to_bullet(tri.v[2]));
  triangle.setMargin(0);
  btBoxShape box({1, 1, 1});
  set_half_extents(box, half);
  btTransform identity;
  identity.setIdentity();
  const std::optional<double> distance = gjk_distance(triangle, identity, box, placement(axes, center));
  return harness::answered(distance && *distance <= 0);
}

}  // namespace cc::bullet_oracle
