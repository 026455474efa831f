#include "harness/judging/bands.h"

#include <cmath>
#include <stdexcept>

namespace cc::harness {

Band library_band(QueryKind kind) {
  switch (kind) {
    case QueryKind::ray_aabb:
      return {0x1p-46, BandSides::conservative, 0x1p-50,
              "slab parameters carry 3 roundings and are padded outward by 8u; a miss shorter than 44u of the "
              "scale can read as a hit. Parallel slabs are decided exactly. t within 4u, plus u to round the "
              "exact t"};
    case QueryKind::sphere_sphere:
      return {0x1p-46, BandSides::conservative, 0,
              "|d|^2 - (r_a+r_b)^2 is certified against an 8u bound: at most 88u of the scale between surfaces"};
    case QueryKind::aabb_aabb: return {0, BandSides::exact, 0, "comparisons of inputs only: exact"};
    case QueryKind::kdop_kdop:
      return {0x1p-48, BandSides::conservative, 0,
              "the overlap test is exact; fitting rounds 2- and 3-term projections outward by 4u of their "
              "magnitude (k = 6 fits exactly)"};
    case QueryKind::obb_obb:
      return {0x1p-40, BandSides::conservative, 0,
              "each axis is certified against 32u of the inputs plus 6 eta (eta = 2^-48, the orthonormality "
              "tolerance) of the extents; the exact reference's parallelepiped differs from the library's box "
              "by eta"};
    case QueryKind::tri_aabb:
      return {0x1p-44, BandSides::conservative, 0,
              "box axes are exact; other axes are certified against 5u |axis|_1 of the coordinates, "
              "measured in the conditioning of the axis"};
    case QueryKind::tri_obb:
      return {0x1p-40, BandSides::conservative, 0,
              "as tri_aabb, plus the rounding of the change into the box's frame and eta of the extents"};
    case QueryKind::tri_tri:
      return {0x1p-44, BandSides::conservative, 0,
              "every axis is certified against 5u |axis|_1 of the coordinates, measured in the conditioning "
              "of the axis (cross products of rounded edges)"};
    case QueryKind::mesh_mesh:
    case QueryKind::mesh_mesh_first:
      return {0x1p-40, BandSides::two_sided, 0,
              "b's triangles move into a's frame in floating point (2^-49 of the scale per coordinate), which "
              "can part touching triangles, then tri_tri's 2^-44; 2^-40 leaves room for the conditioning of "
              "the deciding axis"};
    case QueryKind::broadphase:
      return {0, BandSides::exact, 0, "comparisons of the given bounds only (closed boxes): exact"};
    case QueryKind::ray_mesh:
      return {0x1p-40, BandSides::conservative, 0,
              "intersect_ray_triangle may hit a face the ray misses by 2^-44 R, R <= 2 M; the exact margin is at "
              "most that distance. t is judged against ranges: no later than the exact first point, no earlier "
              "than where the ray comes within that distance of a face's box"};
    case QueryKind::moving_obb:
      return {0x1p-40, BandSides::conservative, 0,
              "at the reported times no axis (as given, not normalised) separates the boxes by more than "
              "2^-40 M; t_first and t_last are judged against the exact window and that of the boxes grown "
              "by the band"};
  }
  throw std::out_of_range("no such query kind");
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

bool within_band(const Band& band, bool says_hit, double margin) {
  if (std::isnan(margin)) return false;
  switch (band.sides) {
    case BandSides::exact: return false;
    case BandSides::conservative: return says_hit && margin <= 0 && -margin <= band.width;
    case BandSides::two_sided: return std::fabs(margin) <= band.width;
  }
  return false;
}

std::string_view to_string(BandSides sides) {
  switch (sides) {
    case BandSides::exact: return "exact";
    case BandSides::conservative: return "conservative";
    case BandSides::two_sided: return "two-sided";
  }
  return "?";
}

std::vector<std::pair<std::string, Band>> all_bands() {
  std::vector<std::pair<std::string, Band>> rows;
  for (QueryKind kind : kAllQueryKinds) rows.emplace_back("library " + std::string(name(kind)), library_band(kind));
  for (const PartyBand& p : kPartyBands) rows.emplace_back(std::string(p.party), p.band);
  return rows;
}

}  // namespace cc::harness
