#include "harness/judging/bands.h"

#include <cmath>
#include <stdexcept>

#include "harness/model/input.h"

namespace cc::harness {

Band library_band(QueryKind kind) {
  return with_kind(kind, []<class In>() { return Query<In>::band; });
}

namespace {

// Every manager is given the boxes as the objects' AABBs and reports the pairs it finds overlapping.
constexpr std::string_view kManagerBand = "AABB::overlap on the given bounds (closed boxes): exact";

struct PartyBand {
  std::string_view party;
  Band band;
};

constexpr PartyBand kPartyBands[] = {
    {"libccd.GJK",
     {0x1p-18, BandSides::two_sided, 0,
      "libccd stops on absolute tolerances (around 1e-6): the band they mean at unit scale"}},
    {"libccd.MPR", {0x1p-18, BandSides::two_sided, 0, "mpr_tolerance = 1e-6, absolute: the band it means at unit scale"}},
    {"fcl.collide(Sphere,Sphere)",
     {0x1p-48, BandSides::two_sided, 0, "|c_a - c_b| > r_a + r_b in floating point, no tolerance"}},
    {"fcl.AABBd::overlap", {0, BandSides::exact, 0, "comparisons of inputs only: exact"}},
    {"fcl.KDOPd<k>::overlap",
     {0x1p-49, BandSides::two_sided, 0, "FCL fits with 2- and 3-term sums rounded to nearest, no outward rounding"}},
    {"fcl.OBBd::overlap",
     {0x1p-17, BandSides::two_sided, 0, "obbDisjoint adds 1e-6 to every |R_ij|: up to 4e-6 of the extents"}},
    {"fcl.collide(Box,Box)",
     {0x1p-40, BandSides::two_sided, 0,
      "ODE's boxBox2: |R_ij| padded by 10 eps max(extent, 1); otherwise rounding only"}},
    {"fcl.shapeTriangleIntersect",
     {0x1p-18, BandSides::two_sided, 0, "libccd MPR with FCL's gjk_default_tolerance 1e-6, absolute"}},
    {"fcl.Intersect::intersect_Triangle",
     {0x1p-40, BandSides::two_sided, 0, "17-axis SAT in floating point with no tolerance: rounding only"}},
    {"fcl.BVHModel<OBBd>",
     {0x1p-38, BandSides::two_sided, 0,
      "leaves by intersect_Triangle (2^-40) on triangles moved by FCL's relative transform; the OBB tests "
      "only prune (|R_ij| + 1e-6)"}},
    {"fcl.BVHModel<OBBRSSd>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<OBBd>"}},
    {"fcl.BVHModel<AABBd>",
     {0x1p-38, BandSides::two_sided, 0,
      "both meshes moved into the world frame in floating point and refitted, then intersect_Triangle (2^-40)"}},
    {"fcl.BVHModel<KDOPd<18>>", {0x1p-38, BandSides::two_sided, 0, "as BVHModel<AABBd>"}},
    {"fcl.NaiveCollisionManager", {0, BandSides::exact, 0, kManagerBand}},
    {"fcl.SaPCollisionManager", {0, BandSides::exact, 0, kManagerBand}},
    {"fcl.SSaPCollisionManager", {0, BandSides::exact, 0, kManagerBand}},
    {"fcl.IntervalTreeCollisionManager", {0, BandSides::exact, 0, kManagerBand}},
    {"fcl.DynamicAABBTreeCollisionManager", {0, BandSides::exact, 0, kManagerBand}},
    {"fcl.DynamicAABBTreeCollisionManager_Array", {0, BandSides::exact, 0, kManagerBand}},
    {"fcl.SpatialHashingCollisionManager", {0, BandSides::exact, 0, kManagerBand}},
    {"fcl.continuousCollide",
     {0x1p-12, BandSides::two_sided, 0,
      "conservative advancement stops within toc_err = 1e-4 of the step and GJK's 1e-6 distance tolerance, "
      "absolute: the band they mean at unit scale"}},
};

}  // namespace

Band party_band(std::string_view party) {
  if (is_library_party(party)) throw std::out_of_range("a library party takes its query's library band");
  for (const PartyBand& p : kPartyBands) {
    if (p.party == party) return p.band;
  }
  throw std::out_of_range("no band for party " + std::string(party));
}

std::vector<std::pair<std::string, Band>> all_bands() {
  std::vector<std::pair<std::string, Band>> rows;
  for (QueryKind kind : kAllQueryKinds) rows.emplace_back("library " + std::string(name(kind)), library_band(kind));
  for (const PartyBand& p : kPartyBands) rows.emplace_back(std::string(p.party), p.band);
  return rows;
}

}  // namespace cc::harness
