// A crosscheck subject made of Bullet's own tests (include/crosscheck/subject.h): build it as a
// shared library and run `crosscheck campaign --subject PATH/libcrosscheck_bullet_subject.so`.
// Each function hands the shapes to Bullet as Bullet's own callers would and returns its answer
// (the triangle tests by GJK with collision margins 0, as an exact test would be asked). It
// stands alone, as a user's subject does: it shares no code with crosscheck's Bullet parties
// (oracle/bullet), though it asks some of the same calls.
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btTriangleMesh.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkConvexCast.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <LinearMath/btAabbUtil2.h>
#include <crosscheck/subject.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

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

// A collision world, made once, for its dispatcher's algorithms (GImpact registered for the
// contact pair test's closest points too).
struct World {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase pairs;
  btCollisionWorld world{&dispatcher, &pairs, &configuration};
  btGImpactCollisionAlgorithm::CreateFunc gimpact;
  World() {
    btGImpactCollisionAlgorithm::registerAlgorithm(&dispatcher);
    for (int other = 0; other < MAX_BROADPHASE_COLLISION_TYPES; ++other) {
      dispatcher.registerClosestPointsCreateFunc(GIMPACT_SHAPE_PROXYTYPE, other, &gimpact);
      dispatcher.registerClosestPointsCreateFunc(other, GIMPACT_SHAPE_PROXYTYPE, &gimpact);
    }
  }
};

btCollisionWorld& world() {
  static World w;
  return w.world;
}

// A mesh's triangles in order (face f is Bullet's triangle f).
std::unique_ptr<btTriangleMesh> triangles_of(const cc_mesh& m) {
  auto t = std::make_unique<btTriangleMesh>();
  for (unsigned f = 0; f < m.face_count; ++f) {
    t->addTriangle(v(m.vertices[m.faces[f][0]]), v(m.vertices[m.faces[f][1]]), v(m.vertices[m.faces[f][2]]), false);
  }
  return t;
}

btTransform placed(const cc_pose& p) {
  btTransform t;
  t.setBasis(btMatrix3x3(p.rotation[0][0], p.rotation[0][1], p.rotation[0][2], p.rotation[1][0], p.rotation[1][1],
                         p.rotation[1][2], p.rotation[2][0], p.rotation[2][1], p.rotation[2][2]));
  t.setOrigin(v(p.translation));
  return t;
}

// The face pairs of the contacts GImpact reports between the two placed meshes (margin 0).
std::vector<cc_face_pair> gimpact_pairs(const cc_mesh& a, const cc_pose& pa, const cc_mesh& b, const cc_pose& pb) {
  struct Pairs final : btCollisionWorld::ContactResultCallback {
    std::vector<cc_face_pair> pairs;
    btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int i, const btCollisionObjectWrapper*,
                             int, int j) override {
      pairs.push_back({static_cast<unsigned>(i), static_cast<unsigned>(j)});
      return 0;
    }
  } contacts;
  if (a.face_count == 0 || b.face_count == 0) return {};
  const auto ta = triangles_of(a), tb = triangles_of(b);
  btGImpactMeshShape shape_a(ta.get()), shape_b(tb.get());
  shape_a.setMargin(0), shape_b.setMargin(0);
  shape_a.updateBound(), shape_b.updateBound();
  btCollisionObject object_a, object_b;
  object_a.setCollisionShape(&shape_a), object_b.setCollisionShape(&shape_b);
  object_a.setWorldTransform(placed(pa)), object_b.setWorldTransform(placed(pb));
  world().contactPairTest(&object_a, &object_b, contacts);
  std::sort(contacts.pairs.begin(), contacts.pairs.end(),
            [](const cc_face_pair& x, const cc_face_pair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  contacts.pairs.erase(std::unique(contacts.pairs.begin(), contacts.pairs.end(),
                                   [](const cc_face_pair& x, const cc_face_pair& y) { return x.a == y.a && x.b == y.b; }),
                       contacts.pairs.end());
  return contacts.pairs;
}

struct AnyWorldContact final : btCollisionWorld::ContactResultCallback {
  bool any = false;
  btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*,
                           int, int) override {
    any = true;
    return 0;
  }
};

// GJK with EPA on two convex shapes, as a distance: the signed distance it reports, its point on
// b and the point on a it gives with it (the point on b plus the distance along its normal).
struct Closest final : btDiscreteCollisionDetectorInterface::Result {
  bool reported = false;
  btScalar distance = 0;
  btVector3 on_a, on_b;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3& normal_on_b, const btVector3& point_on_b, btScalar depth) override {
    reported = true;
    distance = depth;
    on_b = point_on_b;
    on_a = point_on_b + normal_on_b * depth;
  }
};

int gjk_distance(const btConvexShape& a, const btTransform& place_a, const btConvexShape& b, const btTransform& place_b,
                 double* distance, cc_vec3* on_a, cc_vec3* on_b) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver penetration;
  btGjkPairDetector detector(&a, &b, &simplex, &penetration);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  input.m_transformA = place_a;
  input.m_transformB = place_b;
  Closest result;
  detector.getClosestPoints(input, result, nullptr);
  if (!result.reported) return 0;
  *distance = result.distance;
  *on_a = {result.on_a.x(), result.on_a.y(), result.on_a.z()};
  *on_b = {result.on_b.x(), result.on_b.y(), result.on_b.z()};
  return 1;
}

btTransform at(const cc_vec3& p) {
  btTransform t;
  t.setIdentity();
  t.setOrigin(v(p));
  return t;
}

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
  world().contactPairTest(&object_a, &object_b, contact);
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

// As btCollisionWorld casts a ray at a static mesh: a segment (a ray of infinite range cut where
// it has passed the whole mesh) through a BVH of the triangles; the face of the nearest hit.
int crosscheck_ray_mesh(const cc_ray* ray, const cc_mesh* mesh, unsigned* face) {
  if (mesh->face_count == 0) return 0;
  const btVector3 origin = v(ray->origin), dir = v(ray->dir);
  btScalar reach = 0;
  for (unsigned i = 0; i < mesh->vertex_count; ++i) reach = std::max(reach, (v(mesh->vertices[i]) - origin).length());
  const btScalar far = dir.length() > 0 ? 2 * reach / dir.length() + 1 : 0;
  const btScalar t0 = std::isfinite(ray->tmin) ? ray->tmin : -far, t1 = std::isfinite(ray->tmax) ? ray->tmax : far;
  if (!(t0 <= t1)) return 0;
  struct Closest final : btTriangleRaycastCallback {
    using btTriangleRaycastCallback::btTriangleRaycastCallback;
    int face = -1;
    btScalar reportHit(const btVector3&, btScalar fraction, int, int triangle) override {
      face = triangle;
      return fraction;
    }
  };
  const auto triangles = triangles_of(*mesh);
  btBvhTriangleMeshShape shape(triangles.get(), true);
  const btVector3 from = origin + dir * t0, to = origin + dir * t1;
  Closest closest(from, to, 0);
  shape.performRaycast(&closest, from, to);
  if (closest.face < 0) return 0;
  *face = static_cast<unsigned>(closest.face);
  return 1;
}

// GImpact on the two placed meshes, as a btCollisionWorld pairs two concave meshes.
int crosscheck_mesh_mesh(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                         cc_face_pair* pairs, unsigned capacity) {
  const std::vector<cc_face_pair> found = gimpact_pairs(*a, *pose_a, *b, *pose_b);
  std::copy_n(found.begin(), std::min<std::size_t>(found.size(), capacity), pairs);
  return static_cast<int>(found.size());
}

int crosscheck_mesh_mesh_first(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                               cc_face_pair* pair) {
  const std::vector<cc_face_pair> found = gimpact_pairs(*a, *pose_a, *b, *pose_b);
  if (found.empty()) return 0;
  *pair = found.front();
  return 1;
}

// A point where two triangles meet: where an edge of one passes through the other (none for
// triangles that meet only within one plane).
bool meeting_point(const btVector3 (&t)[3], const btVector3 (&u)[3], btVector3& at) {
  for (const auto& [p, q] : {std::pair{&t, &u}, std::pair{&u, &t}}) {
    const btVector3 n = ((*q)[1] - (*q)[0]).cross((*q)[2] - (*q)[0]);
    for (int k = 0; k < 3; ++k) {
      const btVector3 a = (*p)[k], b = (*p)[(k + 1) % 3];
      const double da = n.dot(a - (*q)[0]), db = n.dot(b - (*q)[0]);
      if ((da > 0 && db > 0) || (da < 0 && db < 0) || da == db) continue;
      const btVector3 x = a + (b - a) * (da / (da - db));
      bool inside = true;
      for (int i = 0; i < 3; ++i) inside = inside && ((*q)[(i + 1) % 3] - (*q)[i]).cross(x - (*q)[i]).dot(n) >= 0;
      if (inside) {
        at = x;
        return true;
      }
    }
  }
  return false;
}

// The distance between the placed meshes' surfaces the plain way: every pair of faces through
// GJK (btGjkPairDetector on two btTriangleShapes of margin 0, as Bullet asks a pair of convex
// pieces), the nearest kept; a pair GJK finds overlapping is 0 apart (triangles have no inside),
// at a point where an edge of one passes through the other.
int crosscheck_mesh_mesh_distance(const cc_mesh* a, const cc_pose* pose_a, const cc_mesh* b, const cc_pose* pose_b,
                                  double* distance, cc_vec3* on_a, cc_vec3* on_b) {
  const auto placed = [](const cc_mesh& m, const cc_pose& pose, unsigned f, int k) {
    const cc_vec3& p = m.vertices[m.faces[f][k]];
    const double t[3] = {pose.translation.x, pose.translation.y, pose.translation.z};
    btVector3 out;
    for (int r = 0; r < 3; ++r) out[r] = pose.rotation[r][0] * p.x + pose.rotation[r][1] * p.y + pose.rotation[r][2] * p.z + t[r];
    return out;
  };
  btTransform identity;
  identity.setIdentity();
  bool any = false;
  for (unsigned i = 0; i < a->face_count; ++i) {
    const btVector3 va[3] = {placed(*a, *pose_a, i, 0), placed(*a, *pose_a, i, 1), placed(*a, *pose_a, i, 2)};
    btTriangleShape ta(va[0], va[1], va[2]);
    ta.setMargin(0);
    for (unsigned j = 0; j < b->face_count; ++j) {
      const btVector3 vb[3] = {placed(*b, *pose_b, j, 0), placed(*b, *pose_b, j, 1), placed(*b, *pose_b, j, 2)};
      btTriangleShape tb(vb[0], vb[1], vb[2]);
      tb.setMargin(0);
      double d = 0;
      cc_vec3 pa{}, pb{};
      if (gjk_distance(ta, identity, tb, identity, &d, &pa, &pb) != 1) return 0;
      btVector3 at;
      if (d <= 0 && meeting_point(va, vb, at)) pa = pb = {at.x(), at.y(), at.z()};
      d = std::max(d, 0.0);
      if (!any || d < *distance) *distance = d, *on_a = pa, *on_b = pb, any = true;
    }
  }
  return any ? 1 : 0;
}

// Bullet's dynamic AABB trees (its broad phase), driven as a collision world drives them: a proxy created
// when a box appears, its AABB set every frame, destroyed when the box goes; each frame's
// candidates kept where the boxes overlap (as a narrow phase's first step).
int crosscheck_broadphase(const cc_box_frames* frames, cc_face_pair* pairs, unsigned capacity, unsigned* frame_ends) {
  btDbvtBroadphase trees;
  std::vector<btBroadphaseProxy*> proxies(frames->slots, nullptr);
  unsigned count = 0;
  for (unsigned f = 0; f < frames->frames; ++f) {
    for (unsigned i = 0; i < frames->slots; ++i) {
      const cc_aabb& box = frames->boxes[f * frames->slots + i];
      const bool present = frames->present[f * frames->slots + i] != 0;
      if (present && proxies[i] == nullptr) {
        proxies[i] = trees.createProxy(v(box.lo), v(box.hi), 0, reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)),
                                            btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter, nullptr);
      } else if (present) {
        trees.setAabb(proxies[i], v(box.lo), v(box.hi), nullptr);
      } else if (proxies[i] != nullptr) {
        trees.destroyProxy(proxies[i], nullptr);
        proxies[i] = nullptr;
      }
    }
    trees.calculateOverlappingPairs(nullptr);
    btBroadphasePairArray& candidates = trees.getOverlappingPairCache()->getOverlappingPairArray();
    for (int p = 0; p < candidates.size(); ++p) {
      const auto i = static_cast<unsigned>(reinterpret_cast<std::uintptr_t>(candidates[p].m_pProxy0->m_clientObject));
      const auto j = static_cast<unsigned>(reinterpret_cast<std::uintptr_t>(candidates[p].m_pProxy1->m_clientObject));
      const cc_aabb& a = frames->boxes[f * frames->slots + i];
      const cc_aabb& b = frames->boxes[f * frames->slots + j];
      if (!TestAabbAgainstAabb2(v(a.lo), v(a.hi), v(b.lo), v(b.hi))) continue;
      if (count < capacity) pairs[count] = {i, j};
      ++count;
    }
    frame_ends[f] = std::min(count, capacity);
  }
  for (btBroadphaseProxy* p : proxies) {
    if (p != nullptr) trees.destroyProxy(p, nullptr);
  }
  return static_cast<int>(count);
}

// Distances as Bullet's collision algorithms ask GJK with EPA for closest points: spheres as
// btSphereShapes (a point with the radius as its margin), boxes and triangles with margin 0. Its
// tolerances are absolute (about 1e-3 where GJK hands over to EPA), so it says 2^-9 of the scale.
double crosscheck_distance_tolerance(void) { return 0x1p-9; }

int crosscheck_tri_tri_distance(const cc_triangle* a, const cc_triangle* b, double* distance, cc_vec3* on_a,
                                cc_vec3* on_b) {
  btTriangleShape ta(v(a->v[0]), v(a->v[1]), v(a->v[2])), tb(v(b->v[0]), v(b->v[1]), v(b->v[2]));
  ta.setMargin(0), tb.setMargin(0);
  btTransform identity;
  identity.setIdentity();
  return gjk_distance(ta, identity, tb, identity, distance, on_a, on_b);
}

int crosscheck_sphere_sphere_distance(const cc_sphere* a, const cc_sphere* b, double* distance, cc_vec3* on_a,
                                      cc_vec3* on_b) {
  const btSphereShape sa(a->radius), sb(b->radius);
  return gjk_distance(sa, at(a->center), sb, at(b->center), distance, on_a, on_b);
}

int crosscheck_sphere_obb_distance(const cc_sphere* ball, const cc_obb* box, double* distance, cc_vec3* on_a,
                                   cc_vec3* on_b) {
  const btSphereShape sphere(ball->radius);
  btBoxShape shape(v(box->half));
  shape.setMargin(0);
  shape.setImplicitShapeDimensions(v(box->half));
  return gjk_distance(sphere, at(ball->center), shape, place(*box), distance, on_a, on_b);
}

int crosscheck_obb_obb_distance(const cc_obb* a, const cc_obb* b, double* distance, cc_vec3* on_a, cc_vec3* on_b) {
  btBoxShape shape_a(v(a->half)), shape_b(v(b->half));
  for (btBoxShape* shape : {&shape_a, &shape_b}) shape->setMargin(0);
  shape_a.setImplicitShapeDimensions(v(a->half));
  shape_b.setImplicitShapeDimensions(v(b->half));
  return gjk_distance(shape_a, place(*a), shape_b, place(*b), distance, on_a, on_b);
}

int crosscheck_tri_obb_distance(const cc_triangle* tri, const cc_obb* box, double* distance, cc_vec3* on_a,
                                cc_vec3* on_b) {
  btTriangleShape triangle(v(tri->v[0]), v(tri->v[1]), v(tri->v[2]));
  triangle.setMargin(0);
  btBoxShape shape(v(box->half));
  shape.setMargin(0);
  shape.setImplicitShapeDimensions(v(box->half));
  btTransform identity;
  identity.setIdentity();
  return gjk_distance(triangle, identity, shape, place(*box), distance, on_a, on_b);
}

}  // extern "C"
