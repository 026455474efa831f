// A crosscheck subject made of Bullet's own tests (include/crosscheck/subject.h): build it as a
// shared library and run `crosscheck campaign --subject PATH/libcrosscheck_bullet_subject.so`.
// Each function hands the shapes to Bullet as Bullet's own callers would and returns its answer
// (the triangle tests by GJK with collision margins 0, as an exact test would be asked). It
// stands alone, as a user's subject does: it shares no code with crosscheck's Bullet parties
// (oracle/bullet), though it asks some of the same calls.
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkConvexCast.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <LinearMath/btAabbUtil2.h>
#include <crosscheck/subject.h>

namespace {

btVector3 v(const cc_vec3& p) { return {p.x, p.y, p.z}; }

struct AnyContact final : btDiscreteCollisionDetectorInterface::Result {
  bool any = false;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3&, const btVector3&, btScalar) override { any = true; }
};

// The box's placement: a basis whose columns are its axes, as a rotation (a mirror-image frame,
// which the interface allows, has its third axis negated: the same box).
btTransform place(const cc_obb& b) {
  btVector3 x = v(b.axis[0]), y = v(b.axis[1]), z = v(b.axis[2]);
  if (x.dot(y.cross(z)) < 0) z = -z;
  btTransform t;
  t.setBasis(btMatrix3x3(x.x(), y.x(), z.x(), x.y(), y.y(), z.y(), x.z(), y.z(), z.z()));
  t.setOrigin(v(b.center));
  return t;
}

// GJK with EPA on a triangle and a box (margins 0): a hit when the distance it reports is <= 0.
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

int gjk(const cc_triangle& tri, const btVector3& half, const btTransform& box_place) {
  btTriangleShape triangle(v(tri.v[0]), v(tri.v[1]), v(tri.v[2]));
  triangle.setMargin(0);
  btBoxShape box(half);
  box.setMargin(0);
  box.setImplicitShapeDimensions(half);
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver penetration;
  btGjkPairDetector detector(&triangle, &box, &simplex, &penetration);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  input.m_transformA.setIdentity();
  input.m_transformB = box_place;
  Distance result;
  detector.getClosestPoints(input, result, nullptr);
  return result.reported && result.distance <= 0 ? 1 : 0;
}

// A collision world, made once, for its dispatcher's algorithms.
struct World {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase pairs;
  btCollisionWorld world{&dispatcher, &pairs, &configuration};
};

struct AnyWorldContact final : btCollisionWorld::ContactResultCallback {
  bool any = false;
  btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*,
                           int, int) override {
    any = true;
    return 0;
  }
};

}  // namespace

extern "C" {

int crosscheck_subject_version(void) { return CROSSCHECK_SUBJECT_VERSION; }

int crosscheck_aabb_aabb(const cc_aabb* a, const cc_aabb* b) {
  return TestAabbAgainstAabb2(v(a->lo), v(a->hi), v(b->lo), v(b->hi)) ? 1 : 0;
}

// As btDbvt::rayTest casts a ray: reciprocals with BT_LARGE_FLOAT for 1/0.
int crosscheck_ray_aabb(const cc_ray* ray, const cc_aabb* box) {
  const btVector3 dir = v(ray->dir);
  btVector3 inverse;
  unsigned int sign[3];
  for (int i = 0; i < 3; ++i) {
    inverse[i] = dir[i] == btScalar(0) ? btScalar(BT_LARGE_FLOAT) : btScalar(1) / dir[i];
    sign[i] = inverse[i] < btScalar(0);
  }
  const btVector3 bounds[2] = {v(box->lo), v(box->hi)};
  btScalar t = 0;
  return btRayAabb2(v(ray->origin), inverse, sign, bounds, t, ray->tmin, ray->tmax) ? 1 : 0;
}

// As btBoxBoxCollisionAlgorithm asks its detector.
int crosscheck_obb_obb(const cc_obb* a, const cc_obb* b) {
  btBoxShape box_a(v(a->half)), box_b(v(b->half));
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  input.m_transformA = place(*a);
  input.m_transformB = place(*b);
  AnyContact contact;
  btBoxBoxDetector(&box_a, &box_b).getClosestPoints(input, contact, nullptr);
  return contact.any ? 1 : 0;
}

// Two btSphereShape objects through the world's contact pair test.
int crosscheck_sphere_sphere(const cc_sphere* a, const cc_sphere* b) {
  static World w;
  btSphereShape shape_a(a->radius), shape_b(b->radius);
  btCollisionObject object_a, object_b;
  object_a.setCollisionShape(&shape_a);
  object_b.setCollisionShape(&shape_b);
  btTransform t;
  t.setIdentity();
  t.setOrigin(v(a->center));
  object_a.setWorldTransform(t);
  t.setOrigin(v(b->center));
  object_b.setWorldTransform(t);
  AnyWorldContact contact;
  w.world.contactPairTest(&object_a, &object_b, contact);
  return contact.any ? 1 : 0;
}

int crosscheck_tri_aabb(const cc_triangle* tri, const cc_aabb* box) {
  btTransform t;
  t.setIdentity();
  t.setOrigin((v(box->lo) + v(box->hi)) * btScalar(0.5));
  return gjk(*tri, (v(box->hi) - v(box->lo)) * btScalar(0.5), t);
}

int crosscheck_tri_obb(const cc_triangle* tri, const cc_obb* box) { return gjk(*tri, v(box->half), place(*box)); }

// As Bullet's continuous collision is used: the boxes (default margin) cast over the step by
// btGjkConvexCast, after a discrete test at its start (btBoxBoxDetector).
int crosscheck_moving_obb(const cc_moving_obb* a, const cc_moving_obb* b) {
  if (crosscheck_obb_obb(&a->box, &b->box)) return 1;
  btBoxShape box_a(v(a->box.half)), box_b(v(b->box.half));
  btVoronoiSimplexSolver simplex;
  btGjkConvexCast cast(&box_a, &box_b, &simplex);
  const btTransform a0 = place(a->box), b0 = place(b->box);
  btTransform a1 = a0, b1 = b0;
  a1.setOrigin(a0.getOrigin() + v(a->velocity));
  b1.setOrigin(b0.getOrigin() + v(b->velocity));
  btConvexCast::CastResult result;
  return cast.calcTimeOfImpact(a0, a1, b0, b1, result) && result.m_fraction <= 1 ? 1 : 0;
}

}  // extern "C"
