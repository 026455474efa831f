// ray_mesh's second opinion from Bullet: btBvhTriangleMeshShape::performRaycast with a
// btTriangleRaycastCallback, as btCollisionWorld casts a ray against a static triangle mesh: the
// segment from origin + tmin dir to origin + tmax dir (finite ranges only; its ends rounded
// here, so not asked of segments reaching beyond 8 times the scale of the mesh and the origin),
// against the mesh's faces in a quantized BVH; the face of the smallest hit fraction is its
// answer (the case's first face; no t is compared). Bullet's triangle test takes a face's plane
// by its unnormalised normal and accepts a point whose sub-triangle products with it are at
// least -1e-4 |n|^2: a point outside the face by up to about 1e-4 of its size is a hit, 2^-12
// of the scale; a segment that only touches a face's plane at an end, or lies in it, and a face
// of zero area never hit (two-sided band; a degenerate face's hit is beyond it).
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleMesh.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>

#include <algorithm>
#include <cmath>

#include "oracle/bullet/convert.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {


// Keeps the face of the closest hit (Bullet calls it for each nearer hit it finds).
struct ClosestFace final : btTriangleRaycastCallback {
  using btTriangleRaycastCallback::btTriangleRaycastCallback;
  int face = -1;
  btScalar reportHit(const btVector3&, btScalar fraction, int, int triangle) override {
    face = triangle;
    return fraction;
  }
};

Opinion perform_raycast(const harness::RayMeshInput& in) {
  const Ray& r = in.ray;
  if (in.mesh.mesh == nullptr) return not_applicable("no mesh");
  if (!std::isfinite(r.tmin) || !std::isfinite(r.tmax)) return not_applicable("a ray of infinite length (Bullet casts segments)");
  if (!(r.tmin <= r.tmax)) return not_applicable("an empty parameter range (tmin > tmax)");
  const Mesh& mesh = *in.mesh.mesh;
  double scale = max_abs(r.origin);
  for (const Vec3& p : mesh.vertices) scale = std::max(scale, max_abs(p));
  const Vec3 from = r.tmin == 0 ? r.origin : r.origin + r.tmin * r.dir, to = r.origin + r.tmax * r.dir;
  if (!(std::max(max_abs(from), max_abs(to)) <= 8 * scale)) {
    return not_applicable("the segment reaches beyond 8 times the scale of the mesh and the origin");
  }
  if (mesh.faces.empty()) return answered(false);
  // The quantized BVH keeps 21 bits of a triangle's index (its part the other 10).
  if (mesh.size() >= (1u << 21)) return not_applicable("more faces than the quantized BVH numbers (2^21)");
  btTriangleMesh triangles;  // 32-bit indices, vertices as btVector3 (doubles)
  for (std::uint32_t f = 0; f < mesh.size(); ++f) {
    const Triangle t = mesh.triangle(f);
    triangles.addTriangle(to_bullet(t.v[0]), to_bullet(t.v[1]), to_bullet(t.v[2]), false);
  }
  btBvhTriangleMeshShape shape(&triangles, true);
  ClosestFace closest(to_bullet(from), to_bullet(to), 0);  // back faces hit too
  shape.performRaycast(&closest, to_bullet(from), to_bullet(to));
  if (closest.face < 0) return answered(false);
  harness::Answer a = harness::Answer::of(true);
  a.pairs = {{static_cast<std::uint32_t>(closest.face), 0}};
  return answered(a);
}

}  // namespace

template <>
const std::vector<Party<harness::RayMeshInput>>& bullet_parties() {
  static const std::vector<Party<harness::RayMeshInput>> parties = {
      {"bullet.btBvhTriangleMeshShape::performRaycast",
       {0x1p-12, BandSides::two_sided, 0,
        "a point within -1e-4 |n|^2 of a face's sub-triangle products is inside: about 1e-4 of the face's size; "
        "a segment touching a face's plane only at an end never hits"},
       perform_raycast}};
  return parties;
}

}  // namespace cc::bullet_oracle
