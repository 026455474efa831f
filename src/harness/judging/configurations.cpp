#include "harness/judging/configurations.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "collide/kdop.h"

namespace cc::harness {
namespace {

constexpr double kFar = 0x1p20;             // far from the origin, a long way, an aspect ratio
constexpr double kNearlyParallel = 0x1p-20;  // sine of the angle, below which (but not 0) nearly parallel
constexpr double kJust = 0x1p-40;            // an exact margin this small: nearly touching
constexpr double kAtTheTolerance = 0x1p-49;  // a Gram entry off by this: half the orthonormality tolerance

using Names = std::vector<std::string_view>;

const std::map<QueryKind, Names>& expected() {
  static const std::map<QueryKind, Names> lists = {
      {QueryKind::ray_aabb,
       {"touching", "just apart", "just overlapping", "parallel to a slab", "nearly parallel to a slab",
        "from far away", "negative parameters", "segment", "zero direction", "flat box", "point box", "long box",
        "far from the origin"}},
      {QueryKind::sphere_sphere,
       {"touching", "just apart", "just overlapping", "point", "radii far apart", "concentric", "far from the origin"}},
      {QueryKind::aabb_aabb, {"touching", "flat box", "point box", "identical"}},
      {QueryKind::kdop_kdop,
       {"touching", "just apart", "just overlapping", "single point", "cancelling projection", "far from the origin",
        "k = 6", "k = 14", "k = 16", "k = 18", "k = 24", "k = 26"}},
      {QueryKind::obb_obb,
       {"touching", "just apart", "just overlapping", "parallel axes", "nearly parallel axes",
        "frame at the tolerance", "flat box", "segment box", "point box", "long box", "sizes far apart",
        "far from the origin"}},
      {QueryKind::tri_aabb,
       {"touching", "just apart", "just overlapping", "segment triangle", "point triangle", "sliver", "flat box",
        "point box", "in a face's plane", "nearly in a face's plane", "edge nearly parallel to an axis",
        "far vertex not last", "far from the origin"}},
      {QueryKind::tri_obb,
       {"touching", "just apart", "just overlapping", "segment triangle", "point triangle", "sliver", "flat box",
        "point box", "in a face's plane", "nearly in a face's plane", "edge nearly parallel to an axis",
        "frame at the tolerance", "far vertex not last", "far from the origin"}},
      {QueryKind::tri_tri,
       {"touching", "just apart", "just overlapping", "segment triangle", "point triangle", "sliver", "coplanar",
        "nearly coplanar", "parallel edges", "nearly parallel edges", "far vertex not last", "far from the origin"}},
      {QueryKind::mesh_mesh, {"touching", "exact poses", "rotation at the tolerance", "far from the origin", "degenerate face"}},
      {QueryKind::mesh_mesh_first,
       {"touching", "exact poses", "rotation at the tolerance", "far from the origin", "degenerate face"}},
      {QueryKind::broadphase, {"touching", "identical", "flat box", "added and removed", "many boxes"}},
      {QueryKind::ray_mesh,
       {"touching", "just apart", "grazing a face", "parallel to a face", "from far away", "negative parameters",
        "zero direction", "degenerate face", "far from the origin"}},
      {QueryKind::moving_obb,
       {"touching", "just apart", "parallel axes", "nearly parallel axes", "frame at the tolerance", "fast",
        "no relative motion", "point box", "far from the origin"}},
  };
  return lists;
}

double length(const Vec3& v) { return std::sqrt(dot(v, v)); }

// The sine of the angle between two nonzero vectors (0 for a zero one).
double sine(const Vec3& a, const Vec3& b) {
  const double la = length(a), lb = length(b);
  return la > 0 && lb > 0 ? length(cross(a, b)) / (la * lb) : 0;
}

bool nearly_parallel(const Vec3& a, const Vec3& b) {
  const double s = sine(a, b);
  return s > 0 && s <= kNearlyParallel;
}

bool parallel(const Vec3& a, const Vec3& b) {
  return max_abs(a) > 0 && max_abs(b) > 0 && cross(a, b) == Vec3{};
}

// The largest entry of axes^T axes - I.
double off_orthonormal(const Mat3& m) {
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::fabs(dot(m.col[i], m.col[j]) - (i == j ? 1.0 : 0.0)));
  }
  return worst;
}

int zero_extents(const Vec3& half) { return (half.x == 0) + (half.y == 0) + (half.z == 0); }

bool long_box(const Vec3& half) {
  double lo = INFINITY;
  for (int k = 0; k < 3; ++k) {
    if (half[k] > 0) lo = std::min(lo, half[k]);
  }
  return std::isfinite(lo) && max_abs(half) >= kFar * lo;
}

Vec3 edge(const Triangle& t, int i) { return t.v[(i + 1) % 3] - t.v[i]; }

double longest_edge(const Triangle& t) { return std::max({length(edge(t, 0)), length(edge(t, 1)), length(edge(t, 2))}); }

Vec3 normal(const Triangle& t) { return cross(edge(t, 0), edge(t, 1)); }

bool point(const Triangle& t) { return t.v[0] == t.v[1] && t.v[1] == t.v[2]; }
bool segment(const Triangle& t) { return !point(t) && normal(t) == Vec3{}; }

// Longest edge over height: 2^20 or more.
bool sliver(const Triangle& t) {
  const double area2 = length(normal(t)), e = longest_edge(t);
  return area2 > 0 && e * e >= kFar * area2;
}

// The vertex farthest from p is not the last.
bool far_vertex_not_last(const Triangle& t, const Vec3& p) {
  const auto d = [&p](const Vec3& v) { return length(v - p); };
  return d(t.v[2]) < std::max(d(t.v[0]), d(t.v[1]));
}

double max_coordinate(const Triangle& t) { return std::max({max_abs(t.v[0]), max_abs(t.v[1]), max_abs(t.v[2])}); }

struct Of {
  const ExactVerdict& exact;
  Names names;

  void add(std::string_view name, bool yes) {
    if (yes) names.push_back(name);
  }

  // Touching, and nearly touching either way, by the exact margin.
  void margins() {
    if (exact.contract != Contract::in || !exact.decided) return;
    add("touching", exact.answer.hit && exact.margin == 0);
    add("just apart", exact.margin < 0 && exact.margin >= -kJust);
    add("just overlapping", exact.margin > 0 && exact.margin <= kJust);
  }

  // Far from the origin: the largest coordinate at least 2^20 times the shapes' size.
  void far(double largest, double size) { add("far from the origin", size > 0 && largest >= kFar * size); }

  void boxes(const Vec3& half) {
    add("flat box", zero_extents(half) == 1);
    add("segment box", zero_extents(half) == 2);
    add("point box", zero_extents(half) == 3);
    add("long box", long_box(half));
  }

  void triangle(const Triangle& t) {
    add("segment triangle", segment(t));
    add("point triangle", point(t));
    add("sliver", sliver(t));
  }

  // A triangle against a box with the given axes (its centre at c).
  void triangle_and_box(const Triangle& t, const Mat3& axes, const Vec3& c) {
    triangle(t);
    const Vec3 n = normal(t);
    bool in_plane = false, nearly_in_plane = false, nearly_along = false;
    for (const Vec3& a : axes.col) {
      in_plane |= parallel(n, a);
      nearly_in_plane |= nearly_parallel(n, a);
      for (int i = 0; i < 3; ++i) nearly_along |= nearly_parallel(edge(t, i), a);
    }
    add("in a face's plane", in_plane);
    add("nearly in a face's plane", nearly_in_plane);
    add("edge nearly parallel to an axis", nearly_along);
    add("far vertex not last", far_vertex_not_last(t, c));
  }

  void axes_pair(const Mat3& a, const Mat3& b) {
    bool par = false, nearly = false;
    for (const Vec3& x : a.col) {
      for (const Vec3& y : b.col) par |= parallel(x, y), nearly |= nearly_parallel(x, y);
    }
    add("parallel axes", par);
    add("nearly parallel axes", nearly);
    add("frame at the tolerance", std::max(off_orthonormal(a), off_orthonormal(b)) >= kAtTheTolerance);
  }

  void operator()(const RayAabbInput& in) {
    margins();
    const Ray& r = in.ray;
    const double d = max_abs(r.dir);
    bool par = false, nearly = false;
    for (int k = 0; k < 3; ++k) {
      const bool zero = r.dir[k] == 0 || std::isinf(1.0 / r.dir[k]);
      par |= zero;
      nearly |= !zero && std::fabs(r.dir[k]) <= kNearlyParallel * d;
    }
    add("parallel to a slab", par);
    add("nearly parallel to a slab", nearly);
    const Vec3 half = 0.5 * (in.box.hi - in.box.lo), center = 0.5 * (in.box.lo + in.box.hi);
    const double size = max_abs(half);
    double gap = 0;  // from the origin to the box, per axis at most
    for (int k = 0; k < 3; ++k) gap = std::max({gap, in.box.lo[k] - r.origin[k], r.origin[k] - in.box.hi[k]});
    add("from far away", size > 0 && gap >= kFar * size);
    add("negative parameters", exact.contract == Contract::in && exact.answer.hit && !exact.answer.params.empty() &&
                                   exact.answer.params[0] < 0);
    add("segment", std::isfinite(r.tmax) && r.tmax > 0);
    add("zero direction", d == 0);
    boxes(half);
    far(max_abs(center), size);
  }
  void operator()(const SphereSphereInput& in) {
    margins();
    add("point", in.a.radius == 0 || in.b.radius == 0);
    const double lo = std::min(in.a.radius, in.b.radius), hi = std::max(in.a.radius, in.b.radius);
    add("radii far apart", lo > 0 && hi >= kFar * lo);
    add("concentric", in.a.center == in.b.center);
    far(std::max(max_abs(in.a.center), max_abs(in.b.center)), in.a.radius + in.b.radius);
  }
  void operator()(const AabbAabbInput& in) {
    margins();
    add("flat box", zero_extents(in.a.hi - in.a.lo) > 0 || zero_extents(in.b.hi - in.b.lo) > 0);
    add("point box", zero_extents(in.a.hi - in.a.lo) == 3 || zero_extents(in.b.hi - in.b.lo) == 3);
    add("identical", in.a == in.b);
  }
  void operator()(const KdopKdopInput& in) {
    margins();
    const auto single = [](const std::vector<Vec3>& s) {
      return !s.empty() && std::all_of(s.begin(), s.end(), [&s](const Vec3& p) { return p == s.front(); });
    };
    add("single point", single(in.a) || single(in.b));
    bool cancels = false;
    double largest = 0, lo = INFINITY, hi = -INFINITY;
    for (const std::vector<Vec3>* set : {&in.a, &in.b}) {
      for (const Vec3& p : *set) {
        largest = std::max(largest, max_abs(p));
        lo = std::min(lo, p.x), hi = std::max(hi, p.x);
        for (const KdopDirection& d : kdop_directions(in.k)) {
          const double m = std::fabs(d.x * p.x) + std::fabs(d.y * p.y) + std::fabs(d.z * p.z);
          const double s = d.x * p.x + d.y * p.y + d.z * p.z;
          cancels |= (d.x != 0) + (d.y != 0) + (d.z != 0) > 1 && m > 0 && std::fabs(s) <= kNearlyParallel * m;
        }
      }
    }
    add("cancelling projection", cancels);
    far(largest, hi - lo);
    static constexpr std::string_view kNames[] = {"k = 6", "k = 14", "k = 16", "k = 18", "k = 24", "k = 26"};
    static constexpr int kKs[] = {6, 14, 16, 18, 24, 26};
    for (int i = 0; i < 6; ++i) add(kNames[i], in.k == kKs[i]);
  }
  void operator()(const ObbObbInput& in) {
    margins();
    axes_pair(in.a.axes, in.b.axes);
    boxes(in.a.half), boxes(in.b.half);
    const double sa = max_abs(in.a.half), sb = max_abs(in.b.half);
    add("sizes far apart", std::min(sa, sb) > 0 && std::max(sa, sb) >= kFar * std::min(sa, sb));
    far(std::max(max_abs(in.a.center), max_abs(in.b.center)), std::max(sa, sb));
  }
  void operator()(const TriAabbInput& in) {
    margins();
    const Vec3 half = 0.5 * (in.box.hi - in.box.lo), center = 0.5 * (in.box.lo + in.box.hi);
    triangle_and_box(in.tri, Mat3::identity(), center);
    boxes(half);
    far(std::max(max_coordinate(in.tri), max_abs(center)), std::max(max_abs(half), longest_edge(in.tri)));
  }
  void operator()(const TriObbInput& in) {
    margins();
    triangle_and_box(in.tri, in.box.axes, in.box.center);
    boxes(in.box.half);
    add("frame at the tolerance", off_orthonormal(in.box.axes) >= kAtTheTolerance);
    far(std::max(max_coordinate(in.tri), max_abs(in.box.center)), std::max(max_abs(in.box.half), longest_edge(in.tri)));
  }
  void operator()(const TriTriInput& in) {
    margins();
    triangle(in.a), triangle(in.b);
    const Vec3 na = normal(in.a), nb = normal(in.b);
    bool coplanar = parallel(na, nb);
    for (const Vec3& p : in.b.v) coplanar &= dot(na, p - in.a.v[0]) == 0;
    add("coplanar", coplanar);
    add("nearly coplanar", nearly_parallel(na, nb));
    bool par = false, nearly = false;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) par |= parallel(edge(in.a, i), edge(in.b, j)), nearly |= nearly_parallel(edge(in.a, i), edge(in.b, j));
    }
    add("parallel edges", par);
    add("nearly parallel edges", nearly);
    const Vec3 ca = (1.0 / 3) * (in.a.v[0] + in.a.v[1] + in.a.v[2]), cb = (1.0 / 3) * (in.b.v[0] + in.b.v[1] + in.b.v[2]);
    add("far vertex not last", far_vertex_not_last(in.a, cb) || far_vertex_not_last(in.b, ca));
    far(std::max(max_coordinate(in.a), max_coordinate(in.b)), std::max(longest_edge(in.a), longest_edge(in.b)));
  }
  void meshes(const MeshPair& m) {
    margins();
    const auto exact_pose = [](const RigidTransform& t) { return off_orthonormal(t.rotation) == 0; };
    add("exact poses", exact_pose(m.pose_a) && exact_pose(m.pose_b));
    add("rotation at the tolerance", std::max(off_orthonormal(m.pose_a.rotation), off_orthonormal(m.pose_b.rotation)) >= kAtTheTolerance);
    double size = 0;
    bool degenerate = false;
    for (const MeshRef* r : {&m.a, &m.b}) {
      for (const Vec3& p : r->mesh->vertices) size = std::max(size, max_abs(p));
      for (std::size_t i = 0; i < r->mesh->size() && !degenerate; ++i) degenerate = normal(r->mesh->triangle(i)) == Vec3{};
    }
    add("degenerate face", degenerate);
    far(std::max(max_abs(m.pose_a.translation), max_abs(m.pose_b.translation)), size);
  }
  void operator()(const MeshMeshInput& in) { meshes(in.meshes); }
  void operator()(const MeshMeshFirstInput& in) { meshes(in.meshes); }
  void operator()(const BroadphaseInput& in) {
    bool touching = false, identical = false, flat = false, added_and_removed = false;
    const std::size_t slots = in.frames.empty() ? 0 : in.frames[0].size();
    for (std::size_t i = 0; i < slots; ++i) {
      bool present = false, absent = false;
      for (const auto& frame : in.frames) (frame[i] ? present : absent) = true;
      added_and_removed |= present && absent;
    }
    for (const auto& frame : in.frames) {
      for (std::size_t i = 0; i < frame.size(); ++i) {
        if (!frame[i]) continue;
        flat |= zero_extents(frame[i]->hi - frame[i]->lo) > 0;
        for (std::size_t j = i + 1; j < frame.size(); ++j) {
          if (!frame[j]) continue;
          identical |= *frame[i] == *frame[j];
          for (int k = 0; k < 3; ++k) {
            touching |= (frame[i]->lo[k] == frame[j]->hi[k] || frame[i]->hi[k] == frame[j]->lo[k]) &&
                        test_aabb_aabb(*frame[i], *frame[j]);
          }
        }
      }
    }
    add("touching", touching);
    add("identical", identical);
    add("flat box", flat);
    add("added and removed", added_and_removed);
    add("many boxes", slots >= 40);
  }
  void operator()(const RayMeshInput& in) {
    margins();
    const Mesh& mesh = *in.mesh.mesh;
    bool grazing = false, par = false, degenerate = false;
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (std::size_t i = 0; i < mesh.size(); ++i) {
      const Vec3 n = normal(mesh.triangle(i));
      degenerate |= n == Vec3{};
      const double s = length(n) > 0 && length(in.ray.dir) > 0 ? std::fabs(dot(n, in.ray.dir)) / (length(n) * length(in.ray.dir)) : 1;
      grazing |= s > 0 && s <= kNearlyParallel;
      par |= length(n) > 0 && length(in.ray.dir) > 0 && dot(n, in.ray.dir) == 0;
    }
    for (const Vec3& p : mesh.vertices) {
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    }
    const double size = max_abs(hi - lo);
    double gap = 0;
    for (int k = 0; k < 3; ++k) gap = std::max({gap, lo[k] - in.ray.origin[k], in.ray.origin[k] - hi[k]});
    add("grazing a face", grazing);
    add("parallel to a face", par);
    add("degenerate face", degenerate);
    add("from far away", size > 0 && gap >= kFar * size);
    add("negative parameters", exact.contract == Contract::in && exact.answer.hit && !exact.answer.params.empty() &&
                                   exact.answer.params[0] < 0);
    add("zero direction", in.ray.dir == Vec3{});
    far(std::max(max_abs(lo), max_abs(hi)), size);
  }
  void operator()(const MovingObbInput& in) {
    margins();
    axes_pair(in.a.box.axes, in.b.box.axes);
    const Vec3 v = in.b.velocity - in.a.velocity;
    const double size = std::max(max_abs(in.a.box.half), max_abs(in.b.box.half));
    add("fast", size > 0 && max_abs(v) >= kFar * size);
    add("no relative motion", v == Vec3{});
    add("point box", zero_extents(in.a.box.half) == 3 || zero_extents(in.b.box.half) == 3);
    far(std::max(max_abs(in.a.box.center), max_abs(in.b.box.center)), size);
  }
};

}  // namespace

std::vector<std::string_view> configurations_of(const Input& input, const ExactVerdict& exact) {
  Of of{exact, {}};
  std::visit(of, input);
  return std::move(of.names);
}

std::span<const std::string_view> expected_configurations(QueryKind kind) {
  const auto& lists = expected();
  const auto it = lists.find(kind);
  return it == lists.end() ? std::span<const std::string_view>{} : std::span<const std::string_view>(it->second);
}

}  // namespace cc::harness
