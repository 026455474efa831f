// fast_convex_hull: quickhull in floating point, with a tolerance and no merging of facets.
// Each point is assigned to one facet it lies outside of; the farthest point of a facet is added
// by replacing every facet it sees with a fan from it to their horizon; the points of the
// replaced facets are assigned again to the new ones or left as inside. A point left inside is
// dropped only when it lies, certainly, strictly inside a tetrahedron of points kept (by the
// signs of four orientations, each decided by a filter that certifies it); otherwise it stays among the
// vertices, and so do the hull vertices the hull swallows as it grows. Every point dropped is
// thus inside the hull of the points kept, in exact arithmetic, whatever the rounding did to
// the facets.
#include <algorithm>
#include <cmath>

#include "collide/convex_hull.h"
#include "collide/exact_orientation.h"

namespace cc {
namespace {

using Index = std::uint32_t;

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

constexpr int kNext[3] = {1, 2, 0};  // (e + 1) % 3

// Dot products here sum in order (dot_in_order). The facets and their distances are a fitting
// heuristic with a tolerance (what the hull keeps is certified by orientations, below), so they
// need not be symmetric in the coordinates as the library's tests are (fp::sum3); they are the
// hull's most frequent operations.

// The buffers are kept from one hull to the next (one object per thread): a hierarchy computes
// a hull per node, most of them of a few points.
class QuickHull {
 public:
  void run(std::span<const Vec3> points, ConvexHull& hull) {
    hull.triangles.clear(), hull.vertices.clear();
    p_ = points;
    faces_.clear(), pending_.clear(), kept_.clear();
    const auto n = static_cast<Index>(points.size());
    if (n == 0) return;
    // Coordinates relative to the first point; the extremes along the axes.
    q_.resize(n);
    const Vec3 origin = points[0];
    std::array<Index, 6> extremes{};
    for (Index i = 0; i < n; ++i) {
      q_[i] = points[i] - origin;
      for (int k = 0; k < 3; ++k) {
        if (q_[i][k] < q_[extremes[2 * k]][k]) extremes[2 * k] = i;
        if (q_[i][k] > q_[extremes[2 * k + 1]][k]) extremes[2 * k + 1] = i;
      }
    }
    int axis = 0;
    double extent = 0;
    for (int k = 0; k < 3; ++k) {
      const double e = std::max(-q_[extremes[2 * k]][k], q_[extremes[2 * k + 1]][k]);
      if (q_[extremes[2 * k + 1]][k] - q_[extremes[2 * k]][k] > q_[extremes[2 * axis + 1]][axis] - q_[extremes[2 * axis]][axis]) {
        axis = k;
      }
      extent = std::max(extent, e);
    }
    eps_ = 0x1p-40 * extent + 0x1p-44 * max_abs(origin) + fp::subnormal_slack;
    if (extent == 0) {
      hull.vertices.push_back(0);
      return;
    }
    // The simplex: the extremes along the axis of largest spread, the point farthest from their
    // line, the point farthest from the plane of the three.
    Index a = extremes[2 * axis], b = extremes[2 * axis + 1];
    const Vec3 ab = q_[b] - q_[a];
    Index c = a;
    double far = 0;
    for (Index i = 0; i < n; ++i) {
      const double d = norm_squared(cross(q_[i] - q_[a], ab));
      if (d > far) far = d, c = i;
    }
    if (std::sqrt(far) <= eps_ * std::sqrt(norm_squared(ab))) return all_points(hull);  // collinear
    const Vec3 normal = unit(cross(ab, q_[c] - q_[a]));
    if (n == 3) {  // a triangle, both sides
      hull.triangles.push_back({0, 1, 2});
      hull.triangles.push_back({0, 2, 1});
      return all_points(hull);
    }
    Index d = a;
    far = 0;
    double side = 0;
    for (Index i = 0; i < n; ++i) {
      const double h = dot_in_order(normal, q_[i] - q_[a]);
      if (std::fabs(h) > far) far = std::fabs(h), d = i, side = h;
    }
    if (far <= eps_) return flat(normal, hull);
    if (side > 0) std::swap(b, c);  // d below the face (a, b, c)
    next_.resize(n);
    if (mark_.size() < n) mark_.resize(n, 0);
    const int f0 = add_face(a, b, c), f1 = add_face(a, d, b), f2 = add_face(b, d, c), f3 = add_face(c, d, a);
    link(f0, 0, f1, 2), link(f0, 1, f2, 2), link(f0, 2, f3, 2);
    link(f1, 0, f3, 1), link(f1, 1, f2, 0), link(f2, 1, f3, 0);
    rest_.clear();
    for (Index i = 0; i < n; ++i) {
      if (i != a && i != b && i != c && i != d) rest_.push_back(i);
    }
    const std::array<int, 4> simplex{f0, f1, f2, f3};
    const std::array<std::array<Index, 4>, 1> tetrahedron{{{a, b, c, d}}};
    assign(rest_, simplex, tetrahedron);
    while (!pending_.empty()) {
      const int f = pending_.back();
      pending_.pop_back();
      if (faces_[f].alive && faces_[f].head >= 0) add_farthest_point(f);
    }
    const std::uint32_t taken = next_stamp();
    for (const Face& f : faces_) {
      if (!f.alive) continue;
      hull.triangles.push_back(f.v);
      for (Index v : f.v) {
        if (mark_[v] != taken) mark_[v] = taken, hull.vertices.push_back(v);
      }
    }
    for (Index v : kept_) {
      if (mark_[v] != taken) mark_[v] = taken, hull.vertices.push_back(v);
    }
  }

 private:
  struct Edge {
    Index from, to;
    int outside;  // the face across it that the eye does not see
  };
  struct Step {
    int face, edge, left;  // a visible face, its next edge to look across, how many are left
  };
  struct Planar {
    double u, v;
    Index id;
  };
  struct Face {
    std::array<Index, 3> v;   // counter-clockwise seen from outside
    std::array<int, 3> adj;   // the face across edge v[i] -> v[i + 1]
    Vec3 n;                   // unit outward normal (0 for a degenerate face)
    double offset;            // n . (x - origin) on the face's plane
    int head = -1;            // first point outside it (next_ links the others)
    Index far = 0;            // the farthest of them
    double far_distance = 0;
    bool alive = true;
  };

  static double norm_squared(const Vec3& v) { return dot_in_order(v, v); }
  static Vec3 unit(const Vec3& v) {
    const double n = std::sqrt(norm_squared(v));
    return n > 0 ? (1 / n) * v : Vec3{0, 0, 0};
  }
  [[gnu::always_inline]] double distance(const Face& f, Index i) const { return dot_in_order(f.n, q_[i]) - f.offset; }

  [[gnu::always_inline]] int add_face(Index a, Index b, Index c) {
    Face& f = faces_.emplace_back();
    f.v = {a, b, c};
    f.adj = {-1, -1, -1};
    f.n = unit(cross(q_[b] - q_[a], q_[c] - q_[a]));
    f.offset = dot_in_order(f.n, q_[a]);
    return static_cast<int>(faces_.size() - 1);
  }

  // A fresh value for mark_: points marked with it are those marked since.
  std::uint32_t next_stamp() {
    if (++stamp_ == 0) std::fill(mark_.begin(), mark_.end(), 0), stamp_ = 1;
    return stamp_;
  }
  [[gnu::always_inline]] void link(int f, int edge, int g, int g_edge) { faces_[f].adj[edge] = g, faces_[g].adj[g_edge] = f; }

  // Each point goes to the first face it lies outside of; one outside none is dropped if it lies
  // certainly inside one of the tetrahedra, and kept otherwise.
  void assign(std::span<const Index> points, std::span<const int> faces,
              std::span<const std::array<Index, 4>> tetrahedra) {
    for (Index i : points) {
      bool outside = false;
      for (int f : faces) {
        Face& face = faces_[f];
        const double h = distance(face, i);
        if (h <= eps_) continue;
        if (face.head < 0) pending_.push_back(f);
        if (face.head < 0 || h > face.far_distance) face.far = i, face.far_distance = h;
        next_[i] = face.head, face.head = static_cast<int>(i);
        outside = true;
        break;
      }
      if (outside) continue;
      const bool inside = std::any_of(tetrahedra.begin(), tetrahedra.end(), [&](const std::array<Index, 4>& t) {
        return certainly_inside(t, i);
      });
      if (!inside) kept_.push_back(i);
    }
  }

  // The sign of the orientation of (a, b, c, d) on the points as given when the floating-point
  // filter of exact_orientation.h decides it (then it is exact), 0 when it does not: a point
  // near a face is kept, not decided in integers (nearly flat quads are common and the hull only
  // needs to keep enough points). The filter this used before certified wrong signs where
  // products underflowed beside large terms.
  int orientation(Index a, Index b, Index c, Index d) const {
    return orientation_stages::filtered_orientation_sign(p_[a], p_[b], p_[c], p_[d]).value_or(0);
  }

  // Whether point i lies strictly inside the tetrahedron, certainly: it is on the same side of
  // each face as the opposite corner.
  bool certainly_inside(const std::array<Index, 4>& t, Index i) const {
    const int sign = orientation(t[0], t[1], t[2], t[3]);
    return sign != 0 && orientation(i, t[1], t[2], t[3]) == sign && orientation(t[0], i, t[2], t[3]) == sign &&
           orientation(t[0], t[1], i, t[3]) == sign && orientation(t[0], t[1], t[2], i) == sign;
  }

  void add_farthest_point(int seed) {
    const Index eye = faces_[seed].far;
    // The faces the eye sees, connected to the seed, and their horizon: edges to faces it does
    // not see, which must form one loop (else the eye is dropped: rounding made the hull
    // inconsistent there).
    std::vector<int>& visible = visible_;
    visible.assign(1, seed);
    faces_[seed].alive = false;
    std::vector<Edge>& loop = loop_;
    loop.clear();
    bool simple = true;
    // Depth first from the seed, each face's edges counter-clockwise from the one it was entered
    // by: the horizon comes out as a loop in order.
    std::vector<Step>& path = path_;
    path.assign(1, {seed, 0, 3});
    while (!path.empty()) {
      Step& step = path.back();
      if (step.left == 0) {
        path.pop_back();
        continue;
      }
      const Face& f = faces_[step.face];
      const int e = step.edge;
      step.edge = kNext[e], --step.left;
      const int g = f.adj[e];
      if (!faces_[g].alive) continue;  // seen already
      if (distance(faces_[g], eye) > eps_) {
        faces_[g].alive = false;
        visible.push_back(g);
        // Enter g by its edge back to f; look across its other two edges.
        int back = 0;
        while (faces_[g].adj[back] != step.face) ++back;
        path.push_back({g, kNext[back], 2});
      } else {
        loop.push_back({f.v[e], f.v[kNext[e]], g});
      }
    }
    // The loop must be one closed chain without the eye, each vertex once (else the eye is
    // dropped: rounding made the hull inconsistent there).
    const std::uint32_t on_loop = next_stamp();
    const auto n = static_cast<int>(loop.size());
    for (int k = 0; k < n; ++k) {
      const Edge& e = loop[k];
      simple &= e.from != eye && e.to == loop[k + 1 == n ? 0 : k + 1].from && mark_[e.from] != on_loop;
      mark_[e.from] = on_loop;
    }
    simple &= n > 0;
    if (!simple) {
      for (int f : visible) faces_[f].alive = true;
      drop(seed, eye);
      kept_.push_back(eye);
      if (faces_[seed].head >= 0) pending_.push_back(seed);
      return;
    }
    const auto first = static_cast<int>(faces_.size());
    fresh_.clear();
    for (int k = 0; k < n; ++k) {
      const int f = add_face(loop[k].from, loop[k].to, eye);
      fresh_.push_back(f);
      const Face& out = faces_[loop[k].outside];  // has the horizon edge as to -> from
      for (int e = 0; e < 3; ++e) {
        if (out.v[e] == loop[k].to && out.v[kNext[e]] == loop[k].from) link(f, 0, loop[k].outside, e);
      }
    }
    for (int k = 0; k < n; ++k) link(first + k, 1, first + (k + 1 == n ? 0 : k + 1), 2);
    // The visible faces' vertices off the horizon (which is marked on_loop) are swallowed: kept,
    // as no certificate says they are inside.
    for (int f : visible) {
      for (Index v : faces_[f].v) {
        if (mark_[v] != on_loop) mark_[v] = on_loop, kept_.push_back(v);
      }
    }
    rest_.clear();
    tetrahedra_.clear();
    for (int f : visible) {
      for (int i = faces_[f].head; i >= 0; i = next_[i]) {
        if (static_cast<Index>(i) != eye) rest_.push_back(static_cast<Index>(i));
      }
      faces_[f].head = -1;
      tetrahedra_.push_back({eye, faces_[f].v[0], faces_[f].v[1], faces_[f].v[2]});
    }
    assign(rest_, fresh_, tetrahedra_);
  }

  // Takes the eye out of the seed's outside points (it stays out of the hull).
  void drop(int seed, Index eye) {
    Face& f = faces_[seed];
    rest_.clear();
    for (int i = f.head; i >= 0; i = next_[i]) {
      if (static_cast<Index>(i) != eye) rest_.push_back(static_cast<Index>(i));
    }
    f.head = -1;
    for (Index i : rest_) {
      const double h = distance(f, i);
      if (f.head < 0 || h > f.far_distance) f.far = i, f.far_distance = h;
      next_[i] = f.head, f.head = static_cast<int>(i);
    }
  }

  // Nearly collinear or flat points: nothing is certified, every point is a vertex.
  void all_points(ConvexHull& hull) const {
    hull.vertices.resize(q_.size());
    for (Index i = 0; i < q_.size(); ++i) hull.vertices[i] = i;
  }

  // Points in a plane: the polygon by a monotone chain in the plane, fanned into triangles on
  // both sides (so area-weighted sums are the polygon's counted twice).
  void flat(const Vec3& normal, ConvexHull& hull) {
    const Vec3 e1 = unit(std::fabs(normal.x) < 0.9 ? cross(normal, Vec3{1, 0, 0}) : cross(normal, Vec3{0, 1, 0}));
    const Vec3 e2 = cross(normal, e1);
    std::vector<Planar>& q = planar_;
    q.clear();
    for (Index i = 0; i < q_.size(); ++i) q.push_back({dot_in_order(q_[i], e1), dot_in_order(q_[i], e2), i});
    std::sort(q.begin(), q.end(), [](const Planar& a, const Planar& b) { return a.u != b.u ? a.u < b.u : a.v < b.v; });
    std::vector<Planar>& chain = chain_;
    chain.resize(2 * q.size());
    std::size_t k = 0;
    const auto turns_left = [&](const Planar& r) {
      return cross2(chain[k - 1].u - chain[k - 2].u, chain[k - 1].v - chain[k - 2].v, r.u - chain[k - 2].u,
                    r.v - chain[k - 2].v) > 0;
    };
    for (std::size_t i = 0; i < q.size(); ++i) {
      while (k >= 2 && !turns_left(q[i])) --k;
      chain[k++] = q[i];
    }
    for (std::size_t i = q.size() - 1, lower = k + 1; i-- > 0;) {
      while (k >= lower && !turns_left(q[i])) --k;
      chain[k++] = q[i];
    }
    const std::size_t corners = k - 1;  // the last point repeats the first
    for (std::size_t i = 1; i + 1 < corners; ++i) {
      hull.triangles.push_back({chain[0].id, chain[i].id, chain[i + 1].id});
      hull.triangles.push_back({chain[0].id, chain[i + 1].id, chain[i].id});
    }
    all_points(hull);
  }

  std::span<const Vec3> p_;
  std::vector<Vec3> q_;  // the points relative to the first
  std::vector<Index> kept_;  // points neither on the hull nor certainly inside it
  std::vector<std::array<Index, 4>> tetrahedra_;
  double eps_ = 0;
  std::vector<Face> faces_;
  std::vector<int> next_;
  std::vector<int> pending_;
  std::vector<Index> rest_;
  std::vector<int> visible_, fresh_;
  std::vector<Edge> loop_;
  std::vector<Step> path_;
  std::vector<Planar> planar_, chain_;
  std::vector<std::uint32_t> mark_;  // per point: the stamp it was last marked with
  std::uint32_t stamp_ = 0;
};

}  // namespace

void fast_convex_hull(std::span<const Vec3> points, ConvexHull& hull) {
  thread_local QuickHull quickhull;
  quickhull.run(points, hull);
}

ConvexHull fast_convex_hull(std::span<const Vec3> points) {
  ConvexHull hull;
  fast_convex_hull(points, hull);
  return hull;
}

}  // namespace cc
