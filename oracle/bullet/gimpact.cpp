#include "oracle/bullet/gimpact.h"

#include <BulletCollision/CollisionShapes/btTriangleMesh.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>

#include <algorithm>
#include <memory>

#include "oracle/bullet/collision_world.h"
#include "oracle/bullet/convert.h"

namespace cc::bullet_oracle {
namespace {

// The face pairs of the contacts reported (index0 the first object's face, index1 the second's).
struct FacePairs final : btCollisionWorld::ContactResultCallback {
  std::vector<harness::FacePair> pairs;
  btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int index0, const btCollisionObjectWrapper*,
                           int, int index1) override {
    pairs.emplace_back(static_cast<std::uint32_t>(index0), static_cast<std::uint32_t>(index1));
    return 0;
  }
};

// A mesh as a GImpact shape (its triangles, faces in order) with margin 0.
struct Shape {
  btTriangleMesh triangles;
  std::unique_ptr<btGImpactMeshShape> shape;
  explicit Shape(const Mesh& mesh) {
    for (std::uint32_t f = 0; f < mesh.size(); ++f) {
      const Triangle t = mesh.triangle(f);
      triangles.addTriangle(to_bullet(t.v[0]), to_bullet(t.v[1]), to_bullet(t.v[2]), false);
    }
    shape = std::make_unique<btGImpactMeshShape>(&triangles);
    shape->setMargin(0);
    shape->updateBound();
  }
};

btTransform pose_of(const RigidTransform& t) {
  const Mat3& r = t.rotation;
  btTransform out;
  out.setBasis(btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)));
  out.setOrigin(to_bullet(t.translation));
  return out;
}

}  // namespace

harness::Opinion gimpact_collide(const harness::MeshPair& m, bool first_only) {
  if (m.a.mesh == nullptr || m.b.mesh == nullptr) return harness::not_applicable("no mesh");
  if (m.a.mesh->size() == 0 || m.b.mesh->size() == 0) return harness::not_applicable("a mesh without triangles");
  Shape a(*m.a.mesh), b(*m.b.mesh);
  btCollisionObject object_a, object_b;
  object_a.setCollisionShape(a.shape.get());
  object_b.setCollisionShape(b.shape.get());
  object_a.setWorldTransform(pose_of(m.pose_a));
  object_b.setWorldTransform(pose_of(m.pose_b));
  FacePairs contacts;
  collision_world().contactPairTest(&object_a, &object_b, contacts);
  std::sort(contacts.pairs.begin(), contacts.pairs.end());
  contacts.pairs.erase(std::unique(contacts.pairs.begin(), contacts.pairs.end()), contacts.pairs.end());
  if (first_only && contacts.pairs.size() > 1) contacts.pairs.resize(1);
  harness::Answer answer = harness::Answer::of(!contacts.pairs.empty());
  answer.pairs = std::move(contacts.pairs);
  return harness::answered(answer);
}

}  // namespace cc::bullet_oracle
