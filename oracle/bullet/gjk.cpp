#include "oracle/bullet/gjk.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "oracle/bullet/convert.h"

namespace cc::bullet_oracle {
namespace {

// The distance GJK reports (once, for a valid query).
struct Distance final : btDiscreteCollisionDetectorInterface::Result {
  bool reported = false;
  btScalar distance = 0;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3&, const btVector3&, btScalar depth) override {
    reported = true;
    distance = depth;
  }
};

}  // namespace

std::optional<double> gjk_distance(const btConvexShape& a, const btTransform& place_a, const btConvexShape& b,
                                   const btTransform& place_b) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver penetration;
  btGjkPairDetector gjk(&a, &b, &simplex, &penetration);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  input.m_transformA = place_a;
  input.m_transformB = place_b;
  Distance result;
  gjk.getClosestPoints(input, result, nullptr);
  if (!result.reported) return std::nullopt;
  return result.distance;
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
