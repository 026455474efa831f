#include "harness/judging/features.h"

#include "collide/kdop.h"

namespace cc::harness {
namespace {

bool is_zero(const Vec3& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

bool degenerate(const Triangle& t) { return is_zero(cross(t.v[1] - t.v[0], t.v[2] - t.v[0])); }

bool zero_extent(const Aabb& b) { return b.lo.x == b.hi.x || b.lo.y == b.hi.y || b.lo.z == b.hi.z; }

// Two nonzero vectors with a zero cross product (as computed; exact for the simple values the
// generators use to build parallel configurations).
bool parallel(const Vec3& a, const Vec3& b) { return !is_zero(a) && !is_zero(b) && is_zero(cross(a, b)); }

Vec3 edge(const Triangle& t, int i) { return t.v[(i + 1) % 3] - t.v[i]; }

// A triangle edge or normal parallel to one of the given axes.
bool parallel_to_axes(const Triangle& t, const Mat3& axes) {
  const Vec3 n = cross(edge(t, 0), edge(t, 1));
  for (const Vec3& a : axes.col) {
    if (parallel(n, a)) return true;
    for (int i = 0; i < 3; ++i) {
      if (parallel(edge(t, i), a)) return true;
    }
  }
  return false;
}

struct Of {
  Features operator()(const RayAabbInput& in) const {
    Features f;
    for (int k = 0; k < 3; ++k) f.parallel |= in.ray.dir[k] == 0 || std::isinf(1.0 / in.ray.dir[k]);
    f.degenerate = is_zero(in.ray.dir) || in.ray.tmin == in.ray.tmax || zero_extent(in.box);
    return f;
  }
  Features operator()(const SphereSphereInput& in) const { return {false, false, in.a.radius == 0 || in.b.radius == 0}; }
  Features operator()(const AabbAabbInput& in) const {
    Features f;
    for (int k = 0; k < 3; ++k) {
      f.parallel |= in.a.lo[k] == in.b.hi[k] || in.a.hi[k] == in.b.lo[k] || in.a.lo[k] == in.b.lo[k] ||
                    in.a.hi[k] == in.b.hi[k];
    }
    f.degenerate = zero_extent(in.a) || zero_extent(in.b);
    return f;
  }
  Features operator()(const KdopKdopInput& in) const {
    Features f;
    for (const KdopDirection& d : kdop_directions(in.k)) {
      const Vec3 dir{static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z)};
      for (const Vec3& p : in.a) {
        for (const Vec3& q : in.b) f.parallel |= dot(dir, p) == dot(dir, q);
      }
    }
    const auto single = [](const std::vector<Vec3>& s) {
      for (const Vec3& p : s) {
        if (!(p == s.front())) return false;
      }
      return true;
    };
    f.degenerate = single(in.a) || single(in.b);
    return f;
  }
  Features operator()(const ObbObbInput& in) const {
    Features f;
    for (const Vec3& a : in.a.axes.col) {
      for (const Vec3& b : in.b.axes.col) f.parallel |= parallel(a, b);
    }
    f.degenerate = in.a.half.x == 0 || in.a.half.y == 0 || in.a.half.z == 0 || in.b.half.x == 0 ||
                   in.b.half.y == 0 || in.b.half.z == 0;
    return f;
  }
  Features operator()(const TriAabbInput& in) const {
    return {false, parallel_to_axes(in.tri, Mat3::identity()), degenerate(in.tri) || zero_extent(in.box)};
  }
  Features operator()(const TriObbInput& in) const {
    return {false, parallel_to_axes(in.tri, in.box.axes),
            degenerate(in.tri) || in.box.half.x == 0 || in.box.half.y == 0 || in.box.half.z == 0};
  }
  Features operator()(const TriTriInput& in) const {
    Features f;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) f.parallel |= parallel(edge(in.a, i), edge(in.b, j));
    }
    f.parallel |= parallel(cross(edge(in.a, 0), edge(in.a, 1)), cross(edge(in.b, 0), edge(in.b, 1)));
    f.degenerate = degenerate(in.a) || degenerate(in.b);
    return f;
  }
  Features operator()(const MeshMeshInput& in) const { return of(in.meshes); }
  Features operator()(const MeshMeshFirstInput& in) const { return of(in.meshes); }

  // Parallel: two boxes share a bound value on an axis (equal endpoints). Degenerate: a flat or
  // point box, or two identical boxes.
  Features operator()(const BroadphaseInput& in) const {
    Features f;
    for (const auto& frame : in.frames) {
      for (std::size_t i = 0; i < frame.size(); ++i) {
        if (!frame[i]) continue;
        f.degenerate |= zero_extent(*frame[i]);
        for (std::size_t j = i + 1; j < frame.size() && !(f.parallel && f.degenerate); ++j) {
          if (!frame[j]) continue;
          f.degenerate |= *frame[i] == *frame[j];
          for (int k = 0; k < 3; ++k) f.parallel |= frame[i]->lo[k] == frame[j]->hi[k] || frame[i]->hi[k] == frame[j]->lo[k];
        }
      }
    }
    return f;
  }
  // Parallel: the ray runs along an axis or in the plane of a face. Degenerate: a zero
  // direction or a degenerate face.
  Features operator()(const RayMeshInput& in) const {
    Features f;
    const Mesh& mesh = *in.mesh.mesh;
    for (int k = 0; k < 3; ++k) f.parallel |= in.ray.dir[k] == 0;
    f.degenerate = is_zero(in.ray.dir);
    for (std::size_t i = 0; i < mesh.size(); ++i) {
      const Triangle t = mesh.triangle(i);
      const Vec3 n = cross(edge(t, 0), edge(t, 1));
      f.degenerate |= is_zero(n);
      f.parallel |= !is_zero(n) && dot(n, in.ray.dir) == 0;
    }
    return f;
  }
  // Parallel: parallel box axes, or a rate of exactly 0 along an axis of axis-aligned boxes.
  // Degenerate: a zero half extent, or no relative motion.
  Features operator()(const MovingObbInput& in) const {
    Features f = (*this)(ObbObbInput{in.a.box, in.b.box});
    const Vec3 w = in.b.velocity - in.a.velocity;
    f.parallel |= w.x == 0 || w.y == 0 || w.z == 0;
    f.degenerate |= is_zero(w);
    return f;
  }

  // Parallel: the meshes' frames are aligned up to a permutation and flips of the axes (the
  // relative rotation is a signed permutation), so axis-aligned faces of one are parallel to
  // those of the other. Degenerate: a face of either mesh is a segment or a point.
  static Features of(const MeshPair& m) {
    Features f;
    Mat3 relative_rotation;
    for (int c = 0; c < 3; ++c) relative_rotation.col[c] = transpose_times(m.pose_a.rotation, m.pose_b.rotation.col[c]);
    f.parallel = true;
    for (const Vec3& col : relative_rotation.col) {
      int units = 0, zeros = 0;
      for (int k = 0; k < 3; ++k) units += std::fabs(col[k]) == 1, zeros += col[k] == 0;
      f.parallel &= units == 1 && zeros == 2;
    }
    for (const MeshRef* r : {&m.a, &m.b}) {
      for (std::size_t i = 0; i < r->mesh->size() && !f.degenerate; ++i) f.degenerate = degenerate(r->mesh->triangle(i));
    }
    return f;
  }
};

}  // namespace

Features features_of(const Input& input, const ExactVerdict& exact) {
  Features f = std::visit(Of{}, input);
  f.touching = exact.contract == Contract::in && exact.decided && exact.answer.hit && exact.margin == 0;
  return f;
}

bool parallel_applies(QueryKind kind) { return kind != QueryKind::sphere_sphere; }

}  // namespace cc::harness
