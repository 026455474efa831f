#include "collide/convex_hull.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <optional>
#include <tuple>

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

// Exact arithmetic for the collinear case, on sums of doubles (an error-free product gives a
// product as two doubles, an error-free sum a sum).
std::pair<double, double> two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// Whether the exact sum of the terms is 0: the terms are added one by one into an expansion
// (doubles that do not overlap, by increasing magnitude, whose exact sum is that of the terms
// so far), which sums to 0 exactly when every one of its doubles is 0.
bool sums_to_zero(std::span<const double> terms) {
  std::vector<double> expansion;
  for (double q : terms) {
    for (double& e : expansion) std::tie(q, e) = two_sum(q, e);
    expansion.push_back(q);
  }
  return std::all_of(expansion.begin(), expansion.end(), [](double e) { return e == 0; });
}

// Whether a, b and p lie on one line, exactly: cross(a, b) + cross(b, p) + cross(p, a) = 0 (it
// is cross(b - a, p - a)). The points come scaled by a power of two so that no product
// overflows; nothing when a product is too small to be split exactly into two doubles (never
// when every nonzero coordinate is at least 2^-900 of the largest, scaled to 2^500 or more:
// every product is then at least 2^-800).
std::optional<bool> collinear_exactly(const Vec3& a, const Vec3& b, const Vec3& p) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double factors[6][2] = {{a[i], b[j]}, {-a[j], b[i]}, {b[i], p[j]}, {-b[j], p[i]}, {p[i], a[j]}, {-p[j], a[i]}};
    std::array<double, 12> terms;
    for (int t = 0; t < 6; ++t) {
      const double x = factors[t][0], y = factors[t][1], product = x * y;
      if (x != 0 && y != 0 && !(std::fabs(product) >= 0x1p-960)) return std::nullopt;
      terms[2 * t] = product, terms[2 * t + 1] = std::fma(x, y, -product);
    }
    if (!sums_to_zero(terms)) return false;
  }
  return true;
}

// Coincident points: the first; collinear ones (exactly): the least and the greatest in
// lexicographic order, which along a line are its two ends. Nothing for other points (or when
// collinearity cannot be decided exactly).
std::optional<std::vector<Index>> segment_ends(std::span<const Vec3> points) {
  const auto before = [&](Index i, Index j) {
    const Vec3 &p = points[i], &q = points[j];
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
  };
  Index least = 0, greatest = 0;
  double largest = 0;
  for (Index i = 0; i < points.size(); ++i) {
    if (before(i, least)) least = i;
    if (before(greatest, i)) greatest = i;
    largest = std::max(largest, max_abs(points[i]));
  }
  if (!before(least, greatest)) return std::vector<Index>{least};
  // Scaled so that the largest coordinate lies in [2^500, 2^501): products stay below 2^1002.
  const int scale = 500 - fp::exponent_of(largest);
  std::vector<Vec3> scaled;
  for (const Vec3& p : points) {
    const Vec3 s{fp::scale2(p.x, scale), fp::scale2(p.y, scale), fp::scale2(p.z, scale)};
    if (fp::scale2(s.x, -scale) != p.x || fp::scale2(s.y, -scale) != p.y || fp::scale2(s.z, -scale) != p.z) {
      return std::nullopt;  // scaling down lost a subnormal's bits
    }
    scaled.push_back(s);
  }
  for (const Vec3& p : scaled) {
    if (collinear_exactly(scaled[least], scaled[greatest], p) != true) return std::nullopt;
  }
  return std::vector<Index>{least, greatest};
}

// Points that span a plane (not a line): the polygon by a monotone chain in the plane, fanned
// into triangles on both sides; every point counts as a vertex (a superset of the extreme
// points).
ConvexHull planar_hull(std::span<const Vec3> points) {
  ConvexHull hull;
  hull.vertices.resize(points.size());
  std::iota(hull.vertices.begin(), hull.vertices.end(), Index{0});

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
  if (far == 0 || off == 0) return hull;  // nearly collinear, too nearly for a frame: no area
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
  if (points.empty()) return {};
  if (points.size() >= 4) {
    if (auto hull = qhull_3d(points)) return *hull;
  }
  if (auto ends = segment_ends(points)) return {{}, std::move(*ends)};
  return planar_hull(points);
}

}  // namespace cc
