// The certified quantities of the library's tests, as a probe sees them: each quantity as the
// test computed it, the bound it was certified against (each test's *_bound.h), and what its
// exact counterpart needs. Every certified test has an overload, declared beside its plain
// version, that records into a Records (through bounds::RecordsRef, record_sink.h); the plain
// tests record into NoRecords, which the compiler removes. The overloads return the plain tests'
// answers bit for bit.
//
// Only the harness includes this header: a test's own file includes its bound alone, so a change
// to one bound recompiles that test and what reads the records, not the other tests.
#pragma once

#include <vector>

#include "collide/cube_bound.h"
#include "collide/frame_change_bound.h"
#include "collide/independence_bound.h"
#include "collide/kdop_bound.h"
#include "collide/obb_bound.h"
#include "collide/obb_distance_bound.h"
#include "collide/ray_mesh_bound.h"
#include "collide/ray_slab_bound.h"
#include "collide/ray_triangle_bound.h"
#include "collide/record_sink.h"
#include "collide/sat_bound.h"
#include "collide/sphere_bound.h"
#include "collide/sphere_distance_bound.h"
#include "collide/sweep_bound.h"
#include "collide/triangle_box_distance_bound.h"
#include "collide/triangle_distance_bound.h"
#include "collide/transform_bound.h"
#include "collide/widening.h"

namespace cc::bounds {

/// Every certified quantity one or more probed calls computed, in the order computed.
struct Records {
  std::vector<Quotient> quotients;
  std::vector<SphereSquares> spheres;
  std::vector<KdopProjection> kdop_projections;
  std::vector<ObbTest> obb_tests;
  std::vector<std::vector<ObbAxis>> obb_axes;  // one list per ObbTest
  std::vector<SatAxis> sat_axes;
  std::vector<FrameChange> frame_changes;
  std::vector<Independence> independences;
  std::vector<RayTriangleSlab> ray_triangle_slabs;
  std::vector<RayMeshFaceHit> ray_mesh_hits;
  std::vector<Placement> placements;
  std::vector<RadiusRoot> radius_roots;
  std::vector<Cube> cubes;
  std::vector<SphereSeparation> sphere_separations;
  std::vector<SphereObbSeparation> sphere_obb_separations;
  std::vector<TriangleSeparation> triangle_separations;
  std::vector<ObbSeparation> obb_separations;
  std::vector<TriangleBoxSeparation> triangle_box_separations;

  void add(const Quotient& r) { quotients.push_back(r); }
  void add(const SphereSquares& r) { spheres.push_back(r); }
  void add(const KdopProjection& r) { kdop_projections.push_back(r); }
  void add(const ObbTest& r) { obb_tests.push_back(r), obb_axes.emplace_back(); }
  void add(const ObbAxis& r) { obb_axes.back().push_back(r); }  // after its ObbTest
  void add(const SatAxis& r) { sat_axes.push_back(r); }
  void add(const FrameChange& r) { frame_changes.push_back(r); }
  void add(const Independence& r) { independences.push_back(r); }
  void add(const RayTriangleSlab& r) { ray_triangle_slabs.push_back(r); }
  void add(const RayMeshFaceHit& r) { ray_mesh_hits.push_back(r); }
  void add(const Placement& r) { placements.push_back(r); }
  void add(const RadiusRoot& r) { radius_roots.push_back(r); }
  void add(const Cube& r) { cubes.push_back(r); }
  void add(const SphereSeparation& r) { sphere_separations.push_back(r); }
  void add(const SphereObbSeparation& r) { sphere_obb_separations.push_back(r); }
  void add(const TriangleSeparation& r) { triangle_separations.push_back(r); }
  void add(const ObbSeparation& r) { obb_separations.push_back(r); }
  void add(const TriangleBoxSeparation& r) { triangle_box_separations.push_back(r); }
};

}  // namespace cc::bounds
