#include "oracle/exact/exact_meshes.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "oracle/exact/domain.h"
#include "oracle/exact/judges.h"

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

// Each triangle's bounding box in the world, computed in floating point and widened by a bound
// on its rounding (3 products and 3 sums per coordinate: 2^-50 of their magnitude is ample)
// plus `reach`.
std::vector<Aabb> world_boxes(const Mesh& mesh, const RigidTransform& pose, double reach) {
  std::vector<Aabb> boxes;
  boxes.reserve(mesh.size());
  for (std::size_t f = 0; f < mesh.size(); ++f) {
    Aabb box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (const Vec3& v : mesh.triangle(f).v) {
      for (int i = 0; i < 3; ++i) {
        const Vec3 r = pose.rotation.row(i);
        const double x = r.x * v.x + r.y * v.y + r.z * v.z + pose.translation[i];
        const double err = 0x1p-50 * (std::fabs(r.x * v.x) + std::fabs(r.y * v.y) + std::fabs(r.z * v.z) +
                                      std::fabs(pose.translation[i])) + 0x1p-1000;
        box.lo[i] = std::min(box.lo[i], x - err - reach);
        box.hi[i] = std::max(box.hi[i], x + err + reach);
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

 private:
  const Mesh& mesh_;
  const RigidTransform& pose_;
  std::map<std::uint32_t, QVec3> cache_;
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
  const std::vector<FacePair> candidates =
      overlapping(world_boxes(*m.a.mesh, m.pose_a, reach), world_boxes(*m.b.mesh, m.pose_b, reach));

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
  for (const FacePair& p : candidates) {
    const SatResult r = exact_sat(a.triangle(p.first, "A"), b.triangle(p.second, "B"));
    const double margin = r.margin / scale;
    if (r.hit) v.answer.pairs.push_back(p);
    if (r.hit || margin >= -kNearMargin) v.pair_margins.push_back({p, margin});
  }
  v.answer.hit = !v.answer.pairs.empty();
  v.margin = v.unlisted_margin;
  for (const harness::PairMargin& pm : v.pair_margins) {
    if (std::fabs(pm.margin) < std::fabs(v.margin)) v.margin = pm.margin;
  }
  return v;
}

std::pair<ExactShape, ExactShape> placed_triangles(const MeshPair& m, const FacePair& pair) {
  PlacedVertices a(*m.a.mesh, m.pose_a), b(*m.b.mesh, m.pose_b);
  return {a.triangle(pair.first, "A"), b.triangle(pair.second, "B")};
}

ExactVerdict judge(const harness::MeshMeshInput& in) { return judge_meshes(in.meshes); }
ExactVerdict judge(const harness::MeshMeshFirstInput& in) { return judge_meshes(in.meshes); }

}  // namespace cc::exact
