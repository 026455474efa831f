// Second opinions from FCL 0.7 and libccd, as the harness sees them. All of FCL lives here.
#pragma once

#include "harness/model/oracle.h"

namespace cc::fcl_oracle {

/// Every party, per kind of query:
///   ray_aabb       libccd.GJK, libccd.MPR   (segment vs box with support functions; not
///                                            applicable to rays of infinite length)
///   sphere_sphere  fcl.collide(Sphere,Sphere)
///   aabb_aabb      fcl.AABBd::overlap
///   kdop_kdop      fcl.KDOPd<k>::overlap    (k = 16, 18, 24 only, fitted by FCL)
///   obb_obb        fcl.OBBd::overlap, fcl.collide(Box,Box)
///   tri_aabb       fcl.shapeTriangleIntersect (GJKSolver_libccd, box at the AABB's centre)
///   tri_obb        fcl.shapeTriangleIntersect
///   tri_tri        fcl.Intersect::intersect_Triangle
///   mesh_mesh      fcl.BVHModel<OBBd>, <OBBRSSd>, <AABBd>, <KDOPd<18>> (collide with unlimited
///                  contacts; mesh_mesh_first: one contact)
///   broadphase     fcl.<Manager>CollisionManager for each of FCL's seven managers (Naive, SaP,
///                  SSaP, IntervalTree, DynamicAABBTree, DynamicAABBTree_Array, SpatialHashing),
///                  given the boxes as the objects' AABBs
///   ray_mesh       none (FCL 0.7 has no ray queries): the exact reference and the library's
///                  brute force are the other two opinions
///   moving_obb     fcl.continuousCollide (conservative advancement under translation; not
///                  applicable to boxes with a zero extent)
/// A C++ exception thrown by FCL or libccd is caught and reported as a failed opinion.
class FclSecondOpinion final : public harness::SecondOpinion {
 public:
  FclSecondOpinion();  // checks that FCL's collision matrix has the pairs used
  std::vector<harness::Opinion> opinions(const harness::Input& input) const override;
  std::vector<std::string> parties(harness::QueryKind kind) const override;
  /// The libccd, broadphase and continuous-collision calls abandoned by their time limit or
  /// abort guard so far (time_limit.h).
  int abandoned_calls() const override;
};

}  // namespace cc::fcl_oracle
