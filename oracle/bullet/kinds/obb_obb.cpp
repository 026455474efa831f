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

#include "oracle/bullet/convert.h"
#include "oracle/bullet/parties.h"

namespace cc::bullet_oracle {
namespace {

struct AnyContact final : btDiscreteCollisionDetectorInterface::Result {
  bool any = false;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3&, const btVector3&, btScalar) override { any = true; }
};

Opinion box_box_detector(const harness::ObbObbInput& in) {
  btBoxShape shape_a({1, 1, 1}), shape_b({1, 1, 1});
  set_half_extents(shape_a, in.a.half), set_half_extents(shape_b, in.b.half);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  input.m_transformA = placement(in.a.axes, in.a.center);
  input.m_transformB = placement(in.b.axes, in.b.center);
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
       box_box_detector}};
  return parties;
}

}  // namespace cc::bullet_oracle
