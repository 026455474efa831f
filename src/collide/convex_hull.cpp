#include "collide/convex_hull.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <optional>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace cc {
namespace {

using Index = std::uint32_t;

// Qhull's messages go nowhere: a failure is an exit code, handled below.
FILE* quiet_stream() {
  static FILE* null_stream = std::fopen("/dev/null", "w");
  return null_stream;
}

// The hull of full-dimensional points, with every point that lies on or near the boundary
// ("Qc": coplanar points are kept) among the vertices. Nothing when Qhull fails (flat input).
std::optional<ConvexHull> qhull_3d(std::span<const Vec3> points) {
  std::vector<coordT> coords;
  coords.reserve(points.size() * 3);
  for (const Vec3& p : points) coords.insert(coords.end(), {p.x, p.y, p.z});

  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, quiet_stream());
  char flags[] = "qhull Qt Qc";
  const int exit_code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(), False, flags, nullptr,
                                     quiet_stream());
  std::optional<ConvexHull> hull;
  if (exit_code == 0) {
    hull.emplace();
    std::vector<bool> taken(points.size(), false);
    auto take = [&](pointT* point) {
      const int id = qh_pointid(qh, point);
      if (id >= 0 && !taken[id]) taken[id] = true, hull->vertices.push_back(static_cast<Index>(id));
      return static_cast<Index>(id);
    };
    facetT* facet;
    vertexT *vertex, **vertexp;
    pointT *point, **pointp;
    FORALLfacets {
      std::array<Index, 3> tri{};
      int n = 0;
      FOREACHvertex_(facet->vertices) {
        if (n < 3) tri[n] = take(vertex->point);
        ++n;
      }
      if (n == 3) hull->triangles.push_back(tri);
      FOREACHpoint_(facet->coplanarset) take(point);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int long_blocks = 0, long_bytes = 0;
  qh_memfreeshort(qh, &long_blocks, &long_bytes);
  return hull;
}

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Points that span at most a plane: the polygon by a monotone chain in the plane, fanned into
// triangles on both sides; every point counts as a vertex (a superset of the extreme points).
ConvexHull planar_hull(std::span<const Vec3> points) {
  ConvexHull hull;
  hull.vertices.resize(points.size());
  std::iota(hull.vertices.begin(), hull.vertices.end(), Index{0});
  if (points.size() < 3) return hull;

  // A frame of the plane: the farthest point from the first, then the normal of largest size
  // that a third point makes with them.
  const Vec3 p0 = points[0];
  std::size_t i1 = 0;
  double far = 0, off = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = norm1(points[i] - p0);
    if (d > far) far = d, i1 = i;
  }
  const Vec3 e1 = points[i1] - p0;
  Vec3 normal;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 n = cross(e1, points[i] - p0);
    if (norm1(n) > off) off = norm1(n), normal = n;
  }
  if (far == 0 || off == 0) {  // coincident or collinear: no area
    hull.vertices = {0};
    if (far > 0) hull.vertices.push_back(static_cast<Index>(i1));
    return hull;
  }
  const Vec3 e2 = cross(normal, e1);
  struct Planar {
    double u, v;
    Index id;
  };
  std::vector<Planar> q;
  q.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 d = points[i] - p0;
    q.push_back({dot(d, e1), dot(d, e2), static_cast<Index>(i)});
  }
  std::sort(q.begin(), q.end(), [](const Planar& a, const Planar& b) { return a.u != b.u ? a.u < b.u : a.v < b.v; });
  std::vector<Planar> chain(2 * q.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {  // lower hull
    while (k >= 2 && cross2(chain[k - 1].u - chain[k - 2].u, chain[k - 1].v - chain[k - 2].v, q[i].u - chain[k - 2].u,
                            q[i].v - chain[k - 2].v) <= 0)
      --k;
    chain[k++] = q[i];
  }
  for (std::size_t i = q.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross2(chain[k - 1].u - chain[k - 2].u, chain[k - 1].v - chain[k - 2].v,
                                q[i].u - chain[k - 2].u, q[i].v - chain[k - 2].v) <= 0)
      --k;
    chain[k++] = q[i];
  }
  const std::size_t corners = k - 1;  // the last point repeats the first
  for (std::size_t i = 1; i + 1 < corners; ++i) {
    hull.triangles.push_back({chain[0].id, chain[i].id, chain[i + 1].id});
    hull.triangles.push_back({chain[0].id, chain[i + 1].id, chain[i].id});
  }
  return hull;
}

}  // namespace

ConvexHull convex_hull(std::span<const Vec3> points) {
  if (points.size() >= 4) {
    if (auto hull = qhull_3d(points)) return *hull;
  }
  return planar_hull(points);
}

}  // namespace cc
