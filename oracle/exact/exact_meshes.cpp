#include "oracle/exact/exact_meshes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

#include "oracle/exact/domain.h"
#include "oracle/exact/judges.h"
#include "oracle/exact/triangle_sat.h"

namespace cc::exact {
namespace {

using harness::FacePair;
using harness::MeshPair;

constexpr int kMinExponent = -300, kMaxExponent = 300;

// R v + t, exactly.
QVec3 placed(const RigidTransform& pose, const Vec3& v) {
  const QVec3 q = rational(v);
  QVec3 out;
  for (int i = 0; i < 3; ++i) out[i] = dot(rational(pose.rotation.row(i)), q) + rational(pose.translation[i]);
  return out;
}

double magnitude_of(const MeshPair& m) {
  double mag = std::max(max_abs(m.pose_a.translation), max_abs(m.pose_b.translation));
  for (const Mesh* mesh : {m.a.mesh.get(), m.b.mesh.get()}) {
    for (const Vec3& v : mesh->vertices) mag = std::max(mag, max_abs(v));
  }
  return mag;
}

std::vector<FloatTriangle> float_triangles(const Mesh& mesh, const RigidTransform& pose) {
  std::vector<FloatTriangle> out;
  out.reserve(mesh.size());
  for (std::size_t f = 0; f < mesh.size(); ++f) out.push_back(float_triangle(mesh.triangle(f), pose));
  return out;
}

// Each triangle's bounding box in the world, widened by its rounding bound plus `reach`.
std::vector<Aabb> world_boxes(const std::vector<FloatTriangle>& triangles, double reach) {
  std::vector<Aabb> boxes;
  boxes.reserve(triangles.size());
  for (const FloatTriangle& t : triangles) {
    Aabb box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (const Vec3& v : t.v) {
      for (int i = 0; i < 3; ++i) {
        box.lo[i] = std::min(box.lo[i], v[i] - t.error - reach);
        box.hi[i] = std::max(box.hi[i], v[i] + t.error + reach);
      }
    }
    boxes.push_back(box);
  }
  return boxes;
}

// Pairs of boxes that overlap, by sorting both lists along x.
std::vector<FacePair> overlapping(const std::vector<Aabb>& a, const std::vector<Aabb>& b) {
  std::vector<std::uint32_t> ia(a.size()), ib(b.size());
  for (std::uint32_t i = 0; i < a.size(); ++i) ia[i] = i;
  for (std::uint32_t i = 0; i < b.size(); ++i) ib[i] = i;
  std::sort(ia.begin(), ia.end(), [&](auto x, auto y) { return a[x].lo.x < a[y].lo.x; });
  std::sort(ib.begin(), ib.end(), [&](auto x, auto y) { return b[x].lo.x < b[y].lo.x; });
  std::vector<FacePair> out;
  std::size_t start = 0;
  for (std::uint32_t i : ia) {
    while (start < ib.size() && b[ib[start]].hi.x < a[i].lo.x) ++start;  // b ends before a begins
    for (std::size_t k = start; k < ib.size() && b[ib[k]].lo.x <= a[i].hi.x; ++k) {
      if (test_aabb_aabb(a[i], b[ib[k]])) out.emplace_back(i, ib[k]);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Exact placed vertices, computed once per vertex.
class PlacedVertices {
 public:
  PlacedVertices(const Mesh& mesh, const RigidTransform& pose) : mesh_(mesh), pose_(pose) {}
  const QVec3& operator[](std::uint32_t v) {
    auto it = cache_.find(v);
    if (it == cache_.end()) it = cache_.emplace(v, placed(pose_, mesh_.vertices[v])).first;
    return it->second;
  }
  ExactShape triangle(std::uint32_t face, const std::string& name) {
    const auto& f = mesh_.faces[face];
    return rational_triangle_shape((*this)[f[0]], (*this)[f[1]], (*this)[f[2]], name);
  }
  QTriangle vertices(std::uint32_t face) {
    const auto& f = mesh_.faces[face];
    return {(*this)[f[0]], (*this)[f[1]], (*this)[f[2]]};
  }

 private:
  const Mesh& mesh_;
  const RigidTransform& pose_;
  std::map<std::uint32_t, QVec3> cache_;
};

// A mesh's vertices placed exactly as dyadic points, each computed once.
class DyadicVertices {
 public:
  DyadicVertices(const Mesh& mesh, const RigidTransform& pose) : mesh_(mesh), pose_(pose), placed_(mesh.vertices.size()) {}
  std::array<const DyadicPoint*, 3> triangle(std::uint32_t face) {
    std::array<const DyadicPoint*, 3> out;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh_.faces[face][k];
      if (!placed_[v]) placed_[v] = placed_dyadic(pose_, mesh_.vertices[v]);
      out[k] = &*placed_[v];
    }
    return out;
  }

 private:
  const Mesh& mesh_;
  const RigidTransform& pose_;
  std::vector<std::optional<DyadicPoint>> placed_;
};

bool finite_pose(const RigidTransform& t) { return finite(t.rotation) && finite(t.translation); }

}  // namespace

std::optional<std::string> meshes_outside_domain(const MeshPair& m) {
  for (const auto* r : {&m.a, &m.b}) {
    if (auto problem = mesh_problem(*r->mesh)) return "mesh " + std::string(r == &m.a ? "a" : "b") + ": " + *problem;
  }
  for (const RigidTransform* pose : {&m.pose_a, &m.pose_b}) {
    const std::string which = pose == &m.pose_a ? "pose_a" : "pose_b";
    if (!finite_pose(*pose)) return which + " has a NaN or infinite entry";
    if (auto why = not_orthonormal(pose->rotation)) return which + ": rotation " + *why;
    const Mat3& r = pose->rotation;
    if (dot(cross(r.col[0], r.col[1]), r.col[2]) < 0) return which + ": rotation is a mirror (determinant -1)";
  }
  return scale_outside(magnitude_of(m), kMinExponent, kMaxExponent);
}

harness::ExactVerdict judge_meshes(const MeshPair& m) {
  if (auto why = meshes_outside_domain(m)) return unspecified(*why);
  const double scale = scale_of(magnitude_of(m));
  const double reach = 0.5 * kNearMargin * scale;  // each box, so a gap up to kNearMargin * scale
  const std::vector<FloatTriangle> float_a = float_triangles(*m.a.mesh, m.pose_a),
                                   float_b = float_triangles(*m.b.mesh, m.pose_b);
  const std::vector<FacePair> candidates = overlapping(world_boxes(float_a, reach), world_boxes(float_b, reach));

  harness::ExactVerdict v;
  if (candidates.size() > kMaxNearPairs) {
    v.decided = false;
    v.margin = NAN;
    v.note = std::to_string(candidates.size()) + " pairs of triangles lie within 2^-32 of the scale " +
             std::to_string(scale) + ": too many to test exactly";
    return v;
  }
  v.unlisted_margin = -kNearMargin;
  PlacedVertices a(*m.a.mesh, m.pose_a), b(*m.b.mesh, m.pose_b);
  DyadicVertices dyadic_a(*m.a.mesh, m.pose_a), dyadic_b(*m.b.mesh, m.pose_b);
  thread_local TriangleSat sat;
  const double apart = kNearMargin * scale * (1 + 0x1p-20);
  for (const FacePair& p : candidates) {
    if (certainly_apart(float_a[p.first], float_b[p.second], apart)) continue;  // unlisted either way
    // exact_sat in integers; in rationals where the directions are collinear (rank 1 or 0).
    std::optional<TriangleSatVerdict> r = sat(dyadic_a.triangle(p.first), dyadic_b.triangle(p.second));
    if (!r) {
      const SatResult q = exact_sat(a.triangle(p.first, "A"), b.triangle(p.second, "B"));
      r = TriangleSatVerdict{q.hit, q.rank, q.margin};
    }
    const double margin = r->margin / scale;
    if (r->hit) v.answer.pairs.push_back(p);
    if (r->hit || margin >= -kNearMargin) v.pair_margins.push_back({p, margin});
  }
  v.answer.hit = !v.answer.pairs.empty();
  v.margin = v.unlisted_margin;
  for (const harness::PairMargin& pm : v.pair_margins) {
    if (std::fabs(pm.margin) < std::fabs(v.margin)) v.margin = pm.margin;
  }
  return v;
}

FloatTriangle float_triangle(const Triangle& tri, const RigidTransform& pose) {
  FloatTriangle t;
  for (int k = 0; k < 3; ++k) {
    const Vec3& v = tri.v[k];
    for (int i = 0; i < 3; ++i) {
      const Vec3 r = pose.rotation.row(i);
      t.v[k][i] = r.x * v.x + r.y * v.y + r.z * v.z + pose.translation[i];
      const double err = 0x1p-50 * (std::fabs(r.x * v.x) + std::fabs(r.y * v.y) + std::fabs(r.z * v.z) +
                                    std::fabs(pose.translation[i])) + 0x1p-1000;
      t.error = std::max(t.error, err);
    }
  }
  return t;
}

// From the triangles placed in floating point, with bounds on every rounding (u = 2^-53; D, P
// the largest direction and vertex coordinates, eta the placement error):
//  - a direction (an edge) is off by at most e = 2 eta + 2u D per component; a zero edge in
//    exact arithmetic joins equal vertices of the mesh and is computed as zero too;
//  - a cross product of two by at most e_c = 4 D e + 2 e^2 + 6u D^2 per component;
//  - a projection onto it by at most e_p = 3 e_c (P + eta) + 3 C eta + 9u C P (C its largest
//    component), so the gap by 2 e_p plus its own rounding;
//  - the rank of the directions is 3 (exact_sat then tries the cross product of every pair of
//    them) when a triple product exceeds its bound 3 (e_c (D + e) + C e) + 9u C D;
//  - the conditioning |d_i| |d_j| is at most (|d_i| (1 + 4u) + 2e)(|d_j| (1 + 4u) + 2e).
// `threshold` carries a cushion of 2^-20 for exact_sat's own roundings of the separation.
bool certainly_apart(const FloatTriangle& a, const FloatTriangle& b, double threshold) {
  constexpr double u = fp::u;
  std::array<Vec3, 6> dirs;
  int n = 0;
  double D = 0, P = 0;
  for (const FloatTriangle* t : {&a, &b}) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = t->v[(k + 1) % 3] - t->v[k];
      P = std::max(P, max_abs(t->v[k]));
      if (e.x == 0 && e.y == 0 && e.z == 0) continue;
      dirs[n++] = e;
      D = std::max(D, max_abs(e));
    }
  }
  const double eta = std::max(a.error, b.error);
  const double e = 2 * eta + 2 * u * D;
  const double e_c = 4 * D * e + 2 * e * e + 6 * u * D * D;
  bool rank3 = false;
  for (int i = 0; i < n && !rank3; ++i) {
    for (int j = i + 1; j < n && !rank3; ++j) {
      const Vec3 c = cross(dirs[i], dirs[j]);
      const double C = max_abs(c);
      for (int k = j + 1; k < n && !rank3; ++k) {
        rank3 = std::fabs(dot(c, dirs[k])) > 3 * (e_c * (D + e) + C * e) + 9 * u * C * D;
      }
    }
  }
  if (!rank3) return false;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Vec3 c = cross(dirs[i], dirs[j]);
      const double C = max_abs(c);
      if (C == 0) continue;
      double a_lo = INFINITY, a_hi = -INFINITY, b_lo = INFINITY, b_hi = -INFINITY;
      for (const Vec3& v : a.v) a_lo = std::min(a_lo, dot(c, v)), a_hi = std::max(a_hi, dot(c, v));
      for (const Vec3& v : b.v) b_lo = std::min(b_lo, dot(c, v)), b_hi = std::max(b_hi, dot(c, v));
      const double gap = std::max(b_lo - a_hi, a_lo - b_hi);
      const double e_p = 3 * e_c * (P + eta) + 3 * C * eta + 9 * u * C * P;
      const double gap_low = gap - 2 * e_p - 2 * u * std::fabs(gap);
      const double length_i = std::sqrt(dot(dirs[i], dirs[i])) * (1 + 4 * u) + 2 * e;
      const double length_j = std::sqrt(dot(dirs[j], dirs[j])) * (1 + 4 * u) + 2 * e;
      if (gap_low > threshold * (length_i * length_j * (1 + 4 * u))) return true;
    }
  }
  return false;
}

ExactMeshDistance exact_mesh_distance(const MeshPair& m, std::size_t max_compared) {
  const std::vector<FloatTriangle> float_a = float_triangles(*m.a.mesh, m.pose_a), float_b = float_triangles(*m.b.mesh, m.pose_b);
  const auto boxes_a = world_boxes(float_a, 0), boxes_b = world_boxes(float_b, 0);
  // A pair's lower bound: the distance between the boxes (which hold the exact triangles), each
  // axis' gap lowered by 2^-50 of the coordinates for the subtraction's rounding, the root of the
  // sum of squares by 2^-50 of itself; finite, as a rational.
  const auto lower = [&](const Aabb& p, const Aabb& q) {
    double squares = 0;
    for (int k = 0; k < 3; ++k) {
      const double apart = std::max(p.lo[k] - q.hi[k], q.lo[k] - p.hi[k]);
      const double size = std::max({std::fabs(p.lo[k]), std::fabs(p.hi[k]), std::fabs(q.lo[k]), std::fabs(q.hi[k])});
      const double gap = apart - 0x1p-50 * size;
      if (gap > 0) squares += gap * gap;
    }
    return std::min(std::sqrt(squares) * (1 - 0x1p-50), DBL_MAX);
  };
  // An upper bound on the answer: the least distance between the pairs' first vertices as placed
  // in floating point, plus their placement errors (sqrt(3) e each, 2 e taken) and 2^-50 of
  // itself for its rounding.
  double upper = INFINITY;
  for (const FloatTriangle& p : float_a) {
    for (const FloatTriangle& q : float_b) {
      const Vec3 d = q.v[0] - p.v[0];
      upper = std::min(upper, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) * (1 + 0x1p-50) + 2 * (p.error + q.error));
    }
  }
  // The pairs that may hold the answer, nearest bound first.
  std::vector<std::pair<double, FacePair>> pairs;
  for (std::uint32_t i = 0; i < boxes_a.size(); ++i) {
    for (std::uint32_t j = 0; j < boxes_b.size(); ++j) {
      const double bound = lower(boxes_a[i], boxes_b[j]);
      if (!(bound > upper)) pairs.push_back({bound, {i, j}});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  PlacedVertices a(*m.a.mesh, m.pose_a), b(*m.b.mesh, m.pose_b);
  ExactMeshDistance out;
  double beyond = INFINITY;  // a distance beyond the least found so far
  for (const auto& [bound, pair] : pairs) {
    if (out.faces && (out.squared == 0 || rational(bound) * rational(bound) > out.squared)) break;  // the rest are farther
    // Pairs the float separating-axis filter finds apart by more than the least so far.
    if (certainly_apart(float_a[pair.first], float_b[pair.second], beyond)) continue;
    if (out.pairs_compared == max_compared) {
      out.complete = false;
      return out;
    }
    const Rational d2 = squared_distance_between_triangles(a.vertices(pair.first), b.vertices(pair.second));
    ++out.pairs_compared;
    if (!out.faces || d2 < out.squared) {
      out.squared = d2, out.faces = pair;
      // certainly_apart claims a separation above beyond (1 - 2^-40), and separations are at
      // most distances: beyond is the least distance found, rounded, lifted by 2^-38.
      beyond = root_of(d2) * (1 + 0x1p-38);
    }
  }
  return out;
}

namespace {

// The surface of a mesh placed exactly: a point lies within a tolerance of it when it does of
// one of its faces, those whose placed boxes come near the point tried in rationals.
// It keeps the mesh and the pose: the check outlives the input it was made from.
NearBoundary surface_of(const std::shared_ptr<const Mesh>& mesh, const RigidTransform& pose) {
  struct Surface {
    std::shared_ptr<const Mesh> mesh;
    RigidTransform pose;
    std::vector<Aabb> boxes;
    PlacedVertices placed;
    Surface(std::shared_ptr<const Mesh> m, const RigidTransform& p)
        : mesh(std::move(m)), pose(p), boxes(world_boxes(float_triangles(*mesh, pose), 0)), placed(*mesh, pose) {}
  };
  auto surface = std::make_shared<Surface>(mesh, pose);
  return [surface](const QVec3& point, const Rational& tolerance) {
    const Vec3 p = to_double(point);
    // Boxes farther from p than the tolerance by more than the roundings of p and of the
    // tolerance (2^-50 of their magnitudes) cannot hold a face within it.
    const double reach = to_double(tolerance) * (1 + 0x1p-50) + 0x1p-50 * max_abs(p) + DBL_MIN;
    for (std::uint32_t f = 0; f < surface->boxes.size(); ++f) {
      const Aabb& box = surface->boxes[f];
      bool near = true;
      for (int k = 0; k < 3 && near; ++k) near = p[k] >= box.lo[k] - reach && p[k] <= box.hi[k] + reach;
      if (near && squared_distance_to_triangle(point, surface->placed.vertices(f)) <= tolerance * tolerance) return true;
    }
    return false;
  };
}

}  // namespace

harness::ExactVerdict judge_mesh_distance(const MeshPair& m) {
  if (auto why = meshes_outside_domain(m)) return unspecified(*why);
  const ExactMeshDistance d = exact_mesh_distance(m, kMaxDistancePairs);
  if (!d.complete) {
    harness::ExactVerdict v;
    v.decided = false;
    v.margin = NAN;
    v.note = "more than " + std::to_string(kMaxDistancePairs) +
             " pairs of triangles may hold the distance (the placement's rounding, at this scale, blurs which): too "
             "many to compare exactly";
    return v;
  }
  return distance_verdict(ExactSignedDistance{d.squared}, magnitude_of(m), surface_of(m.a.mesh, m.pose_a),
                          surface_of(m.b.mesh, m.pose_b));
}

std::pair<ExactShape, ExactShape> placed_triangles(const MeshPair& m, const FacePair& pair) {
  PlacedVertices a(*m.a.mesh, m.pose_a), b(*m.b.mesh, m.pose_b);
  return {a.triangle(pair.first, "A"), b.triangle(pair.second, "B")};
}

}  // namespace cc::exact
