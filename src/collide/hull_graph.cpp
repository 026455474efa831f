// hull_graph: quickhull on exact orientation signs. Each point is assigned to one facet it lies
// strictly outside of; the farthest point of a facet (by a floating-point distance, a heuristic
// only) is added by replacing every facet that sees it strictly with a fan from it to their
// horizon; the points of the replaced facets are assigned again to the new facets or, seen by
// none, are inside the new hull (quickhull's invariant, which holds when every sign is exact).
// Points on a facet's plane are never outside it, so coplanar facets stay as triangles of one
// planar face and the hull is never wrong for want of merging.
#include "collide/hull_graph.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

#include "collide/exact_orientation.h"

namespace cc {
namespace {

using Index = std::uint32_t;
constexpr Index kNone = std::numeric_limits<Index>::max();

// orientation_sign decides every finite input, and hull_graph takes finite points only.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return *orientation_sign(a, b, c, d); }

int planar_orientation(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
  return *planar_orientation_sign(a, b, c, drop);
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  return planar_orientation(a, b, c, 0) == 0 && planar_orientation(a, b, c, 1) == 0 &&
         planar_orientation(a, b, c, 2) == 0;
}

// The edges of the hull as pairs of indices into `p`, each edge once or twice.
using Edges = std::vector<std::pair<Index, Index>>;

// Collinear points: the two ends.
Edges segment_edges(std::span<const Vec3> p) {
  Index lo = 0, hi = 0;
  for (Index i = 1; i < p.size(); ++i) {
    if (lexicographic_less(p[i], p[lo])) lo = i;
    if (lexicographic_less(p[hi], p[i])) hi = i;
  }
  return {{lo, hi}};
}

// Coplanar points (not collinear): the polygon by Andrew's monotone chain on the projection that
// drops coordinate `drop` (which keeps the plane's orientation signs: the plane is not parallel
// to that axis), keeping strict turns only.
Edges polygon_edges(std::span<const Vec3> p, int drop) {
  const int a = (drop + 1) % 3, b = (drop + 2) % 3;
  std::vector<Index> order(p.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index i, Index j) {
    return p[i][a] != p[j][a] ? p[i][a] < p[j][a] : p[i][b] < p[j][b];
  });
  std::vector<Index> chain;
  const auto add = [&](Index i, std::size_t floor) {
    while (chain.size() >= floor + 2 &&
           planar_orientation(p[chain[chain.size() - 2]], p[chain.back()], p[i], drop) <= 0) {
      chain.pop_back();
    }
    chain.push_back(i);
  };
  for (Index i : order) add(i, 0);
  const std::size_t lower = chain.size() - 1;
  for (std::size_t k = order.size() - 1; k-- > 0;) add(order[k], lower);
  chain.pop_back();  // the first point again
  Edges edges;
  for (std::size_t k = 0; k < chain.size(); ++k) edges.emplace_back(chain[k], chain[(k + 1) % chain.size()]);
  return edges;
}

class ExactQuickHull {
 public:
  explicit ExactQuickHull(std::span<const Vec3> p) : p_(p) {}

  // Full-dimensional points, with i0..i3 not coplanar.
  Edges edges(Index i0, Index i1, Index i2, Index i3) {
    const std::array<Index, 4> t = {i0, i1, i2, i3};
    for (int k = 0; k < 4; ++k) {
      std::array<Index, 3> v = {t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      if (orientation(p_[v[0]], p_[v[1]], p_[v[2]], p_[t[k]]) > 0) std::swap(v[1], v[2]);  // the fourth below
      facets_.push_back({v, {kNone, kNone, kNone}, {}, true, 0});
    }
    for (Index f = 0; f < 4; ++f) {
      for (int e = 0; e < 3; ++e) facets_[f].adjacent[e] = facet_with_edge(facets_[f].v[(e + 1) % 3], facets_[f].v[e], 4);
    }
    for (Index q = 0; q < p_.size(); ++q) {
      if (q != i0 && q != i1 && q != i2 && q != i3) assign(q, 0);
    }
    for (Index f = 0; f < facets_.size(); ++f) {
      if (facets_[f].alive && !facets_[f].outside.empty()) add_farthest(f);
    }
    Edges out;
    for (const Facet& f : facets_) {
      if (!f.alive) continue;
      for (int e = 0; e < 3; ++e) out.emplace_back(f.v[e], f.v[(e + 1) % 3]);
    }
    return out;
  }

  // After edges(): the vertices all of whose facets lie in one plane, i.e. points inside a face
  // of the hull (not extreme, and not on an edge of it either).
  std::vector<Index> inside_faces() const {
    std::vector<Index> first_facet(p_.size(), kNone);
    std::vector<bool> bent(p_.size(), false);
    for (Index f = 0; f < facets_.size(); ++f) {
      if (!facets_[f].alive) continue;
      for (Index v : facets_[f].v) {
        if (first_facet[v] == kNone) {
          first_facet[v] = f;
        } else if (!bent[v]) {
          const Facet& g = facets_[first_facet[v]];
          for (Index w : facets_[f].v) {  // (g's own vertices are on its plane)
            if (w != g.v[0] && w != g.v[1] && w != g.v[2]) bent[v] = bent[v] || side(g, w) != 0;
          }
        }
      }
    }
    std::vector<Index> out;
    for (Index v = 0; v < p_.size(); ++v) {
      if (first_facet[v] != kNone && !bent[v]) out.push_back(v);
    }
    return out;
  }

 private:
  struct Facet {
    std::array<Index, 3> v;         // outward: the hull is on the negative side
    std::array<Index, 3> adjacent;  // across the edge (v[e], v[e + 1])
    std::vector<Index> outside;     // points assigned to it, strictly on its positive side
    bool alive = true;
    unsigned mark = 0;  // == epoch_: visible from the point being added
  };

  Index facet_with_edge(Index a, Index b, Index among) const {
    for (Index f = 0; f < among; ++f) {
      for (int e = 0; e < 3; ++e) {
        if (facets_[f].v[e] == a && facets_[f].v[(e + 1) % 3] == b) return f;
      }
    }
    return kNone;
  }

  int side(const Facet& f, Index q) const { return orientation(p_[f.v[0]], p_[f.v[1]], p_[f.v[2]], p_[q]); }

  // Assigns q to the first facet from `first` on that it lies strictly outside of, if any.
  void assign(Index q, std::size_t first) {
    for (std::size_t f = first; f < facets_.size(); ++f) {
      if (facets_[f].alive && side(facets_[f], q) > 0) {
        facets_[f].outside.push_back(q);
        return;
      }
    }
  }

  // Adds the farthest point outside facet f (and, through the facets that replace f, every point
  // outside them, before returning).
  void add_farthest(Index f0) {
    std::vector<Index> work = {f0};
    while (!work.empty()) {
      const Index f = work.back();
      work.pop_back();
      if (!facets_[f].alive || facets_[f].outside.empty()) continue;
      const Index apex = farthest(facets_[f]);
      const std::size_t first_new = facets_.size();
      replace_visible(f, apex);
      for (std::size_t n = first_new; n < facets_.size(); ++n) work.push_back(static_cast<Index>(n));
    }
  }

  Index farthest(const Facet& f) const {
    const Vec3 &a = p_[f.v[0]], &b = p_[f.v[1]], &c = p_[f.v[2]];
    const Vec3 normal = cross(b - a, c - a);
    Index best = f.outside.front();
    double far = -std::numeric_limits<double>::infinity();
    for (Index q : f.outside) {
      const Vec3 d = p_[q] - a;
      const double h = normal.x * d.x + normal.y * d.y + normal.z * d.z;
      if (h > far) far = h, best = q;
    }
    return best;
  }

  void replace_visible(Index start, Index apex) {
    ++epoch_;
    // The facets apex sees strictly: a connected set (for exact signs) around `start`.
    std::vector<Index> visible = {start};
    facets_[start].mark = epoch_;
    for (std::size_t k = 0; k < visible.size(); ++k) {
      const Index f = visible[k];
      for (int e = 0; e < 3; ++e) {
        const Index g = facets_[f].adjacent[e];
        if (facets_[g].mark == epoch_) continue;
        if (side(facets_[g], apex) > 0) {
          facets_[g].mark = epoch_;
          visible.push_back(g);
        }
      }
    }
    // One new facet (a, b, apex) per horizon edge (a, b) of a visible facet; they are linked
    // to each other through their ends.
    std::vector<Index> created;
    for (Index f : visible) {
      for (int e = 0; e < 3; ++e) {
        const Index g = facets_[f].adjacent[e];
        if (facets_[g].mark == epoch_) continue;
        const Index a = facets_[f].v[e], b = facets_[f].v[(e + 1) % 3];
        const auto n = static_cast<Index>(facets_.size());
        facets_.push_back({{a, b, apex}, {g, kNone, kNone}, {}, true, 0});
        for (int h = 0; h < 3; ++h) {
          if (facets_[g].v[h] == b && facets_[g].v[(h + 1) % 3] == a) facets_[g].adjacent[h] = n;
        }
        created.push_back(n);
      }
    }
    // The horizon is a cycle through each of its vertices once (the visible facets form a disc).
    for (Index n : created) {
      for (Index m : created) {
        if (facets_[m].v[0] == facets_[n].v[1]) facets_[n].adjacent[1] = m;  // across (b, apex): the facet from b
        if (facets_[m].v[1] == facets_[n].v[0]) facets_[n].adjacent[2] = m;  // across (apex, a): the facet to a
      }
    }
    const std::size_t first_new = facets_.size() - created.size();
    for (Index f : visible) {
      facets_[f].alive = false;
      for (Index q : facets_[f].outside) {
        if (q != apex) assign(q, first_new);
      }
      facets_[f].outside = {};
    }
  }

  std::span<const Vec3> p_;
  std::vector<Facet> facets_;
  unsigned epoch_ = 0;
};

// The edges of the hull of distinct points; for full-dimensional points, `inside` (if given)
// gets the vertices that lie inside a face of the hull.
Edges hull_edges(std::span<const Vec3> p, std::vector<Index>* inside) {
  if (p.size() < 2) return {};
  if (p.size() == 2) return {{0, 1}};
  Index i2 = 2;
  while (i2 < p.size() && collinear(p[0], p[1], p[i2])) ++i2;
  if (i2 == p.size()) return segment_edges(p);
  Index i3 = 2;
  while (i3 < p.size() && (i3 == i2 || orientation(p[0], p[1], p[i2], p[i3]) == 0)) ++i3;
  if (i3 == p.size()) {
    int drop = 0;
    while (planar_orientation(p[0], p[1], p[i2], drop) == 0) ++drop;
    return polygon_edges(p, drop);
  }
  ExactQuickHull hull(p);
  Edges edges = hull.edges(0, 1, i2, i3);
  if (inside != nullptr) *inside = hull.inside_faces();
  return edges;
}

}  // namespace

std::optional<HullGraph> hull_graph(std::span<const Vec3> input) {
  for (const Vec3& p : input) {
    if (!finite(p)) return std::nullopt;
  }
  // Distinct points, in the order of their first occurrence.
  std::vector<Index> order(input.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return lexicographic_less(input[a], input[b]); });
  std::vector<Index> firsts;
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || input[order[k]] != input[order[k - 1]]) firsts.push_back(order[k]);
  }
  std::sort(firsts.begin(), firsts.end());
  std::vector<Vec3> p;
  p.reserve(firsts.size());
  for (Index i : firsts) p.push_back(input[i]);

  std::vector<Index> inside;
  Edges edges = hull_edges(p, &inside);
  if (!inside.empty()) {
    // Again without the points inside faces, whose neighbours all lie in their face: a
    // direction into the hull climbs from none of them.
    std::vector<bool> keep(p.size(), false);
    for (const auto& [a, b] : edges) keep[a] = keep[b] = true;
    for (Index i : inside) keep[i] = false;
    std::vector<Vec3> vertices;
    for (Index i = 0; i < p.size(); ++i) {
      if (keep[i]) vertices.push_back(p[i]);
    }
    p = std::move(vertices);
    edges = hull_edges(p, nullptr);
  }

  // The vertices the edges use, in input order, and their neighbour lists.
  std::vector<Index> renumber(p.size(), kNone);
  for (const auto& [a, b] : edges) renumber[a] = renumber[b] = 0;
  if (p.size() == 1) renumber[0] = 0;
  HullGraph g;
  for (Index i = 0; i < p.size(); ++i) {
    if (renumber[i] == kNone) continue;
    renumber[i] = static_cast<Index>(g.points.size());
    g.points.push_back(p[i]);
  }
  std::vector<std::vector<Index>> adjacent(g.points.size());
  for (const auto& [a, b] : edges) {
    adjacent[renumber[a]].push_back(renumber[b]);
    adjacent[renumber[b]].push_back(renumber[a]);
  }
  g.offsets.push_back(0);
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    g.neighbours.insert(g.neighbours.end(), list.begin(), list.end());
    g.offsets.push_back(static_cast<Index>(g.neighbours.size()));
  }
  return g;
}

}  // namespace cc
