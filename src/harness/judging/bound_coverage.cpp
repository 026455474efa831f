#include "harness/judging/bound_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "harness/formats/input_json.h"
#include "harness/model/mesh_collide.h"

namespace cc::harness {
namespace {

constexpr ExpectedTerm kExpected[] = {
    {QueryKind::ray_aabb, "intersect_ray_aabb", "slab parameter", "rounding"},
    {QueryKind::ray_aabb, "intersect_ray_aabb", "slab parameter", "total"},
    {QueryKind::sphere_sphere, "test_sphere_sphere", "squares", "distance"},
    {QueryKind::sphere_sphere, "test_sphere_sphere", "squares", "reach"},
    {QueryKind::sphere_sphere, "test_sphere_sphere", "squares", "total"},
    {QueryKind::kdop_kdop, "fit_kdop", "projection", "pad"},
    {QueryKind::kdop_kdop, "fit_kdop", "projection", "total"},
    {QueryKind::obb_obb, "test_obb_obb", "axis", "rounding"},
    {QueryKind::obb_obb, "test_obb_obb", "axis", "frame"},
    {QueryKind::obb_obb, "test_obb_obb", "axis", "total"},
    {QueryKind::tri_aabb, "test_triangle_aabb", "axis", "projection"},
    {QueryKind::tri_aabb, "test_triangle_aabb", "axis", "total"},
    {QueryKind::tri_obb, "test_triangle_obb", "frame change", "rounding"},
    {QueryKind::tri_obb, "test_triangle_obb", "frame change", "orthonormality"},
    {QueryKind::tri_obb, "test_triangle_obb", "frame change", "total"},
    {QueryKind::tri_obb, "test_triangle_obb", "axis", "projection"},
    {QueryKind::tri_obb, "test_triangle_obb", "axis", "total"},
    {QueryKind::tri_tri, "test_triangle_triangle", "axis", "projection"},
    {QueryKind::tri_tri, "test_triangle_triangle", "axis", "total"},
    {QueryKind::tri_tri, "test_triangle_triangle", "coplanarity", "rounding"},
    {QueryKind::tri_tri, "test_triangle_triangle", "coplanarity", "total"},
    {QueryKind::ray_mesh, "intersect_ray_triangle", "slab", "projection"},
    {QueryKind::ray_mesh, "intersect_ray_triangle", "slab", "speed"},
    {QueryKind::ray_mesh, "intersect_ray_triangle", "slab", "total"},
    {QueryKind::ray_mesh, "intersect_ray_triangle", "triangle parameter", "rounding"},
    {QueryKind::ray_mesh, "intersect_ray_triangle", "triangle parameter", "total"},
    {QueryKind::ray_mesh, "ray_mesh_closest", "face hit", "origin"},
    {QueryKind::ray_mesh, "ray_mesh_closest", "face hit", "mesh"},
    {QueryKind::ray_mesh, "ray_mesh_closest", "face hit", "total"},
    {QueryKind::moving_obb, "sweep_obb_obb", "axis", "rounding"},
    {QueryKind::moving_obb, "sweep_obb_obb", "axis", "frame"},
    {QueryKind::moving_obb, "sweep_obb_obb", "axis", "total"},
    {QueryKind::moving_obb, "sweep_obb_obb", "obb time", "rounding"},
    {QueryKind::moving_obb, "sweep_obb_obb", "obb time", "total"},
    {QueryKind::moving_obb, "sweep_aabb_aabb", "aabb time", "rounding"},
    {QueryKind::moving_obb, "sweep_aabb_aabb", "aabb time", "total"},
    {QueryKind::mesh_mesh, "object_bounds", "placement", "rotation"},
    {QueryKind::mesh_mesh, "object_bounds", "placement", "translation"},
    {QueryKind::mesh_mesh, "object_bounds", "placement", "total"},
    {QueryKind::mesh_mesh, "object_bounds", "radius", "rounding"},
    {QueryKind::mesh_mesh, "object_bounds", "radius", "total"},
    {QueryKind::mesh_mesh, "object_bounds", "cube", "orthonormality"},
    {QueryKind::mesh_mesh, "object_bounds", "cube", "placement"},
    {QueryKind::mesh_mesh, "object_bounds", "cube", "total"},
};

// The mesh queries' objects are measured alike.
QueryKind measured_as(QueryKind kind) { return kind == QueryKind::mesh_mesh_first ? QueryKind::mesh_mesh : kind; }

template <int K>
void fit_both(const KdopKdopInput& in, bounds::Records& r) {
  fit_kdop<K>(in.a, r);
  fit_kdop<K>(in.b, r);
}

// The object bounds of a placed mesh: its fitted box, its radius and its cube, apart from the
// other mesh's (the cube is checked against this mesh's vertices).
bounds::Records object_bounds(const Mesh& mesh, const RigidTransform& pose) {
  bounds::Records r;
  fitted_box(mesh, pose, r);
  bounding_cube(rotation_radius(mesh, r), pose, r);
  return r;
}

struct Probe {
  std::vector<bounds::Records>& out;
  bounds::Records& r() { return out.emplace_back(); }

  void operator()(const RayAabbInput& in) { intersect_ray_aabb(in.ray, in.box, r()); }
  void operator()(const SphereSphereInput& in) { test_sphere_sphere(in.a, in.b, r()); }
  void operator()(const AabbAabbInput&) {}
  void operator()(const KdopKdopInput& in) {
    switch (in.k) {
      case 6: return fit_both<6>(in, r());
      case 14: return fit_both<14>(in, r());
      case 16: return fit_both<16>(in, r());
      case 18: return fit_both<18>(in, r());
      case 24: return fit_both<24>(in, r());
      case 26: return fit_both<26>(in, r());
    }
  }
  void operator()(const ObbObbInput& in) { test_obb_obb(in.a, in.b, r()); }
  void operator()(const TriAabbInput& in) { test_triangle_aabb(in.tri, in.box, r()); }
  void operator()(const TriObbInput& in) { test_triangle_obb(in.tri, in.box, r()); }
  void operator()(const TriTriInput& in) { test_triangle_triangle(in.a, in.b, r()); }
  void operator()(const MeshMeshInput& in) { meshes(in.meshes); }
  void operator()(const MeshMeshFirstInput& in) { meshes(in.meshes); }
  void operator()(const BroadphaseInput&) {}
  void operator()(const RayMeshInput& in) {
    with_bv_type(in.library.bv, [&]<class BV>() {
      const auto bvh = cached_bvh<BV>(in.mesh.mesh, in.library.build);
      ray_mesh_closest(*bvh, in.ray, r());
    });
  }
  void operator()(const MovingObbInput& in) {
    bounds::Records& records = r();
    sweep_obb_obb(in.a, in.b, records);
    if (in.a.box.axes == Mat3::identity() && in.b.box.axes == Mat3::identity()) {
      const auto box = [](const Obb& b) { return Aabb{b.center - b.half, b.center + b.half}; };
      sweep_aabb_aabb(box(in.a.box), in.a.velocity, box(in.b.box), in.b.velocity, records);
    }
  }
  void meshes(const MeshPair& m) {
    out.push_back(object_bounds(*m.a.mesh, m.pose_a));
    out.push_back(object_bounds(*m.b.mesh, m.pose_b));
  }
};

bool is_total(std::string_view term) { return term == "total"; }

// error / term. A term's error counts beyond fp::subnormal_slack, which every total holds for
// results in the subnormal range (where a relative term may be 0).
double ratio(const TermError& e) {
  const double error = is_total(e.term) ? e.error : std::max(0.0, e.error - fp::subnormal_slack);
  if (error == 0) return 0;
  return e.bound > 0 ? error / e.bound : INFINITY;
}

TermCoverage row_of(std::string_view test, std::string_view quantity, std::string_view term) {
  TermCoverage row;
  row.test = test, row.quantity = quantity, row.term = term;
  return row;
}

}  // namespace

std::span<const ExpectedTerm> expected_terms() { return kExpected; }

bool TermCoverage::ok() const {
  if (largest > 1) return false;
  return is_total(term) || closest >= kApproachFactor;
}

std::string_view test_of(QueryKind kind, std::string_view quantity) {
  for (const ExpectedTerm& e : kExpected) {
    if (e.kind == measured_as(kind) && e.quantity == quantity) return e.test;
  }
  return name(kind);
}

std::vector<bounds::Records> probe_library(const Input& input) {
  std::vector<bounds::Records> out;
  std::visit(Probe{out}, input);
  return out;
}

CaseCoverage BoundCoverage::add(const Input& input, const ExactReference& exact) {
  CaseCoverage added;
  const ExactVerdict verdict = exact.judge(input);
  if (verdict.contract != Contract::in || !verdict.decided) return added;
  added.measured = true;
  const QueryKind kind = kind_of(input);
  const bool near_boundary = std::fabs(verdict.margin) <= kNearBoundary;
  std::set<std::size_t> met;
  std::string json;  // the inputs, written when first needed
  const auto inputs = [&] {
    if (json.empty()) json = input_to_json(input).dump();
    return json;
  };
  for (const bounds::Records& records : probe_library(input)) {
    for (const TermError& e : exact.bound_errors(records)) {
      const std::string_view test = test_of(kind, e.family);
      auto it = std::find_if(rows_.begin(), rows_.end(), [&](const TermCoverage& row) {
        return row.test == test && row.quantity == e.family && row.term == e.term;
      });
      if (it == rows_.end()) {
        rows_.push_back(row_of(test, e.family, e.term));
        it = rows_.end() - 1;
      }
      const double r = ratio(e);
      if (r > it->largest) it->largest = r, it->largest_case = inputs();
      if (r > added.largest) added.largest = r, added.where = it->test + " " + it->quantity + " " + it->term;
      // A term's approach counts where its error could decide an answer; a total's, everywhere.
      // (The object bounds are containers whatever the query's answer.)
      if (!is_total(e.term) && !(e.decisive && (near_boundary || test == "object_bounds"))) continue;
      ++it->quantities;
      met.insert(static_cast<std::size_t>(it - rows_.begin()));
      if (r > it->closest) it->closest = r, it->closest_case = inputs();
    }
  }
  for (std::size_t i : met) ++rows_[i].cases;
  return added;
}

std::vector<TermCoverage> BoundCoverage::rows(std::span<const QueryKind> kinds) const {
  const auto wanted = [&](QueryKind k) {
    return kinds.empty() || std::any_of(kinds.begin(), kinds.end(), [&](QueryKind q) { return measured_as(q) == k; });
  };
  std::vector<TermCoverage> out;
  for (const ExpectedTerm& e : kExpected) {
    if (!wanted(e.kind)) continue;
    const auto it = std::find_if(rows_.begin(), rows_.end(), [&](const TermCoverage& row) {
      return row.test == e.test && row.quantity == e.quantity && row.term == e.term;
    });
    out.push_back(it != rows_.end() ? *it : row_of(e.test, e.quantity, e.term));
  }
  for (const TermCoverage& row : rows_) {
    const bool expected = std::any_of(std::begin(kExpected), std::end(kExpected), [&](const ExpectedTerm& e) {
      return row.test == e.test && row.quantity == e.quantity && row.term == e.term;
    });
    if (!expected) out.push_back(row);
  }
  return out;
}

std::string format_coverage(const std::vector<TermCoverage>& rows) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-24s %-20s %-16s %10s %11s %8s  %s\n", "test", "quantity", "term", "closest",
                "quantities", "cases", "");
  out += line;
  for (const TermCoverage& row : rows) {
    std::string closest = "-";
    if (row.closest > 0 && std::isfinite(row.closest)) {
      std::snprintf(line, sizeof line, "2^%.1f", std::log2(row.closest));
      closest = line;
    } else if (row.closest > 0) {
      closest = "inf";
    }
    std::string note;
    if (row.largest > 1) {
      note = is_total(row.term) ? "EXCEEDED: the bound does not hold" : "EXCEEDED: the term does not cover its error";
    } else if (row.quantities == 0) {
      note = "not measured";
    } else if (!row.ok()) {
      note = "never approached within 2^-8";
    }
    std::snprintf(line, sizeof line, "%-24s %-20s %-16s %10s %11ld %8ld  %s\n", row.test.c_str(), row.quantity.c_str(),
                  row.term.c_str(), closest.c_str(), row.quantities, row.cases, note.c_str());
    out += line;
  }
  return out;
}

}  // namespace cc::harness
