// A kind's second opinions from FCL and libccd (internal to oracle/fcl): each party's name, band
// and call, declared together in the kind's unit, oracle/fcl/kinds/<kind>.cpp. A kind whose unit
// does not define fcl_parties<its input>() fails to link (fcl_oracle.cpp asks every kind's).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "harness/model/party.h"
#include "harness/model/input.h"

namespace cc::fcl_oracle {

using harness::answered;
using harness::Band;
using harness::BandSides;
using harness::failed;
using harness::timed_out;
using harness::not_applicable;
using harness::Opinion;
using harness::Party;

/// The second opinions on inputs of type In, in the order they are asked and stored.
template <class In>
const std::vector<Party<In>>& fcl_parties();

/// FCL's BVHModel collision on two placed meshes with volume type BV, all contacts or only the
/// first (fcl_meshes.cpp, for the mesh kinds' units): the colliding pairs, sorted.
enum class Volume { obb, obbrss, aabb, kdop18, kios, rss };
Opinion fcl_collide_models(Volume volume, const harness::MeshPair& m, bool first_only);

/// The BVHModel parties on two placed meshes, asked for every contact, by name (for the
/// commands and benchmarks that compare hierarchies; defined with those parties): their names, and
/// the opinion of one, with its name and band, whatever the library's hierarchy (those asked of
/// sphere trees only in cases answer here too). Throws std::out_of_range for another name.
std::vector<std::string> fcl_mesh_parties();
Opinion fcl_collide_meshes(const std::string& party, const harness::MeshPair& m);

/// FCL's contacts on two placed meshes (BVHModel<OBBRSSd>, every contact, enable_contact set, as
/// a contact solver asks): for each, the pair (face of a, face of b), the point in the world, the
/// normal and the penetration depth (fcl_meshes.cpp). FCL 0.7 gives up to two per colliding pair,
/// the deepest vertices of one triangle below the other's plane.
struct FclContact {
  std::uint32_t face_a = 0, face_b = 0;
  Vec3 position, normal;
  double depth = 0;
};
std::vector<FclContact> fcl_mesh_contacts(const harness::MeshPair& m);

/// FCL's distance between two placed meshes (BVHModel<RSSd> or <OBBRSSd>, fcl_meshes.cpp), with
/// nearest points as FCL gives them (world coordinates) and the faces they lie on; for the
/// benchmarks that compare mesh distance. Throws std::invalid_argument for another volume type.
struct FclMeshDistance {
  double distance = 0;
  Vec3 on_a, on_b;
  std::uint32_t face_a = 0, face_b = 0;
};
FclMeshDistance fcl_mesh_distance(Volume volume, const harness::MeshPair& m);

/// FCL's GJKSolver_libccd::shapeTriangleIntersect of a box (half extents, axes, centre) and a
/// triangle, under the libccd time limit (fcl_shapes.cpp, for the kinds of a triangle and a box).
Opinion fcl_shape_triangle(const Vec3& half, const Mat3& axes, const Vec3& center, const Triangle& t);

/// True when FCL's collision matrix (libccd solver) has the shape pairs the units use.
bool fcl_supports_used_pairs();

}  // namespace cc::fcl_oracle
