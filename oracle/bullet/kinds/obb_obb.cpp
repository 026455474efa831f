// obb_obb's second opinion from Bullet: btBoxBoxDetector (a port of ODE's dBoxBox), the detector
// of btBoxBoxCollisionAlgorithm, asked as that algorithm asks it (getClosestPoints on the two
// world transforms); a hit when it reports a contact. Each btBoxShape is given its half extents
// exactly (collision margin 0, its implicit dimensions set to them: a box's default margin of
// 0.04 is subtracted and added back, which rounds), its frame made proper (a box is symmetric).
// Its separating-axis test is plain floating point on the face axes, and adds fudge2 = 1e-5
// (absolute) to every |R_ij| before the nine edge axes: their radii grow by up to 1e-5 times
// the sum of four extents, 4e-5 of the scale; 2^-14 two-sided (rounding elsewhere is far
// smaller). A box it finds touching or overlapping must also yield a contact point from its
// clipping; none is a miss.
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>

#include "collide/proper_frame.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {

struct AnyContact final : btDiscreteCollisionDetectorInterface::Result {
  bool any = false;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3&, const btVector3&, btScalar) override { any = true; }
};

// The box as a btBoxShape with exactly its half extents (margin 0).
void set_box(btBoxShape& shape, const Obb& box) {
  shape.setMargin(0);
  shape.setImplicitShapeDimensions({box.half.x, box.half.y, box.half.z});
}

btTransform placement(const Obb& box) {
  const Mat3 r = proper_frame(box.axes);  // columns: the box's axes in the world
  btTransform t;
  t.setBasis(btMatrix3x3(r.col[0].x, r.col[1].x, r.col[2].x, r.col[0].y, r.col[1].y, r.col[2].y, r.col[0].z, r.col[1].z,
                         r.col[2].z));
  t.setOrigin({box.center.x, box.center.y, box.center.z});
  return t;
}

Opinion boxes(const harness::ObbObbInput& in) {
  btBoxShape shape_a({1, 1, 1}), shape_b({1, 1, 1});
  set_box(shape_a, in.a), set_box(shape_b, in.b);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  input.m_transformA = placement(in.a);
  input.m_transformB = placement(in.b);
  AnyContact contact;
  btBoxBoxDetector(&shape_a, &shape_b).getClosestPoints(input, contact, nullptr);
  return answered(contact.any);
}

}  // namespace

template <>
const std::vector<Party<harness::ObbObbInput>>& bullet_parties() {
  static const std::vector<Party<harness::ObbObbInput>> parties = {
      {"bullet.btBoxBoxDetector",
       {0x1p-14, BandSides::two_sided, 0, "fudge2 = 1e-5 added to every |R_ij| before the edge axes: up to 4e-5 of the extents"},
       boxes}};
  return parties;
}

}  // namespace cc::bullet_oracle
