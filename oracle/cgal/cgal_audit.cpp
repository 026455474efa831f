// CGAL's answers (cgal_audit.h). Every double becomes the rational it is (a CGAL point or
// number built from doubles is exact), and each shape becomes CGAL objects: an axis-aligned box
// an Iso_cuboid_3; a sphere its centre and radius; a ray a Ray_3, Segment_3, Point_3 or two
// Ray_3 (a line) by its parameter range; a triangle a Triangle_3, or a Segment_3 or Point_3 when degenerate; an
// oriented box (the parallelepiped its axes span) the union of the six tetrahedra of its Kuhn
// triangulation, or of two triangles, a segment or a point when half extents are 0. Two shapes
// made of pieces meet iff some pair of their pieces does. A k-DOP's slab is the least and the
// greatest scalar product (FT) of its direction with the set's points. A ray meets a mesh where
// its parts meet a face's pieces: CGAL constructs each intersection (a point or a segment) and
// the first t is the least parameter of their points, bracketed by doubles at the end. A disc
// meets a wall where CGAL's squared distance from its centre (Point_2) to the wall (Segment_2 or
// Point_2) is at most the squared radius.
#include "oracle/cgal/cgal_audit.h"

#include <CGAL/Distance_2/Point_2_Point_2.h>
#include <CGAL/Distance_2/Point_2_Segment_2.h>
#include <CGAL/Distance_3/Point_3_Plane_3.h>
#include <CGAL/Distance_3/Point_3_Point_3.h>
#include <CGAL/Distance_3/Point_3_Segment_3.h>
#include <CGAL/Distance_3/Point_3_Tetrahedron_3.h>
#include <CGAL/Distance_3/Point_3_Triangle_3.h>
#include <CGAL/Distance_3/Segment_3_Segment_3.h>
#include <CGAL/Distance_3/Triangle_3_Triangle_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/Intersections_3/Iso_cuboid_3_Iso_cuboid_3.h>
#include <CGAL/Intersections_3/Iso_cuboid_3_Point_3.h>
#include <CGAL/Intersections_3/Iso_cuboid_3_Ray_3.h>
#include <CGAL/Intersections_3/Iso_cuboid_3_Segment_3.h>
#include <CGAL/Intersections_3/Iso_cuboid_3_Triangle_3.h>
#include <CGAL/Intersections_3/Point_3_Ray_3.h>
#include <CGAL/Intersections_3/Point_3_Segment_3.h>
#include <CGAL/Intersections_3/Point_3_Tetrahedron_3.h>
#include <CGAL/Intersections_3/Point_3_Triangle_3.h>
#include <CGAL/Intersections_3/Ray_3_Segment_3.h>
#include <CGAL/Intersections_3/Ray_3_Triangle_3.h>
#include <CGAL/Intersections_3/Segment_3_Segment_3.h>
#include <CGAL/Intersections_3/Segment_3_Tetrahedron_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Tetrahedron_3_Tetrahedron_3.h>
#include <CGAL/Intersections_3/Tetrahedron_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "collide/kdop.h"
#include "collide/mesh.h"
#include "oracle/exact/distance_check.h"

namespace cc::cgal {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Segment = K::Segment_3;
using Triangle3 = K::Triangle_3;
using Tetrahedron = K::Tetrahedron_3;
using Cuboid = K::Iso_cuboid_3;

/// A closed piece of a shape, never degenerate.
using Piece = std::variant<Point, Segment, Triangle3, Tetrahedron>;
using Pieces = std::vector<Piece>;

Point point(const Vec3& v) { return {v.x, v.y, v.z}; }
Vector vector(const Vec3& v) { return {v.x, v.y, v.z}; }

void require(bool in_contract, const char* what) {
  if (!in_contract) throw std::invalid_argument(std::string("cgal_answer: ") + what);
}

void require_finite(std::initializer_list<Vec3> points) {
  for (const Vec3& p : points) require(finite(p), "a coordinate is NaN or infinite");
}

Cuboid cuboid(const Aabb& box) {
  require_finite({box.lo, box.hi});
  for (int k = 0; k < 3; ++k) require(box.lo[k] <= box.hi[k], "inverted box");
  return {point(box.lo), point(box.hi)};
}

/// A triangle; collinear vertices span the segment between the two extreme ones (the
/// lexicographic order of points on a line is their order along it).
Piece triangle_piece(const std::array<Point, 3>& p) {
  if (!CGAL::collinear(p[0], p[1], p[2])) return Triangle3(p[0], p[1], p[2]);
  const auto [lo, hi] = std::minmax_element(p.begin(), p.end());
  if (*lo == *hi) return *lo;
  return Segment(*lo, *hi);
}

Pieces pieces(const Triangle& t) {
  require_finite({t.v[0], t.v[1], t.v[2]});
  return {triangle_piece({point(t.v[0]), point(t.v[1]), point(t.v[2])})};
}

/// The parallelepiped { center + sum u_i half_i axes.col[i] : |u_i| <= 1 }.
Pieces pieces(const Obb& b) {
  require_finite({b.center, b.half, b.axes.col[0], b.axes.col[1], b.axes.col[2]});
  Point corner = point(b.center);
  std::vector<Vector> edges;  // the full edge of each axis that spans
  for (int i = 0; i < 3; ++i) {
    require(b.half[i] >= 0, "negative half extent");
    const Vector c = vector(b.axes.col[i]);
    if (b.half[i] == 0 || c == CGAL::NULL_VECTOR) continue;
    const FT h(b.half[i]);
    corner = corner - c * h;
    edges.push_back(c * (2 * h));
  }
  Pieces out;
  if (edges.empty()) {
    out = {corner};
  } else if (edges.size() == 1) {
    out = {Segment(corner, corner + edges[0])};
  } else if (edges.size() == 2) {
    const Point far = corner + edges[0] + edges[1];
    out = {Triangle3(corner, corner + edges[0], far), Triangle3(corner, corner + edges[1], far)};
  } else {
    // Kuhn: one tetrahedron per order of the three edges, along the diagonal corner..far.
    const Point far = corner + edges[0] + edges[1] + edges[2];
    std::array<int, 3> order = {0, 1, 2};
    // Each positively oriented: CGAL 5.5's squared_distance(Point_3, Tetrahedron_3) takes a
    // point on the negative side of any face as outside, so on a negatively oriented one it
    // measures points inside as outside.
    do {
      const Point p1 = corner + edges[order[0]], p2 = p1 + edges[order[1]];
      const Tetrahedron t(corner, p1, p2, far);
      out.push_back(t.orientation() == CGAL::NEGATIVE ? Tetrahedron(p1, corner, p2, far) : t);
    } while (std::next_permutation(order.begin(), order.end()));
  }
  for (const Piece& piece : out) {
    std::visit(
        [](const auto& s) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, Point>) {
            require(!s.is_degenerate(), "axes not independent");
          }
        },
        piece);
  }
  return out;
}

template <class A, class B>
bool meet(const A& a, const B& b) {
  if constexpr (std::is_same_v<A, Point> && std::is_same_v<B, Point>) {
    return a == b;
  } else {
    return CGAL::do_intersect(a, b);
  }
}

bool meet(const Pieces& a, const Pieces& b) {
  for (const Piece& p : a) {
    for (const Piece& q : b) {
      if (std::visit([](const auto& x, const auto& y) { return meet(x, y); }, p, q)) return true;
    }
  }
  return false;
}

bool meet(const Pieces& a, const Cuboid& box) {
  for (const Piece& p : a) {
    if (std::visit([&](const auto& x) { return CGAL::do_intersect(x, box); }, p)) return true;
  }
  return false;
}

using Ray3 = K::Ray_3;
/// A part of a ray's points: never Line_3 (see ray_parts).
using RayPart = std::variant<Point, Segment, Ray3>;

/// The ray's points { origin + t dir : tmin <= t <= tmax }: a Point_3 when dir is 0 or tmin =
/// tmax, a Segment_3 (tmin, tmax finite), a Ray_3 (one of them infinite), a line as its two Ray_3
/// from the origin; nothing when tmin > tmax.
std::vector<RayPart> ray_parts(const Ray& ray) {
  require_finite({ray.origin, ray.dir});
  require(!std::isnan(ray.tmin) && !std::isnan(ray.tmax) && ray.tmin != INFINITY && ray.tmax != -INFINITY,
          "tmin = +inf, tmax = -inf or NaN");
  if (ray.tmin > ray.tmax) return {};
  const Point o = point(ray.origin);
  const Vector dir = vector(ray.dir);
  const bool from = std::isfinite(ray.tmin), to = std::isfinite(ray.tmax);
  if (dir == CGAL::NULL_VECTOR || ray.tmin == ray.tmax) {
    return {from ? o + dir * FT(ray.tmin) : (to ? o + dir * FT(ray.tmax) : o)};
  }
  if (from && to) return {Segment(o + dir * FT(ray.tmin), o + dir * FT(ray.tmax))};
  if (from) return {Ray3(o + dir * FT(ray.tmin), dir)};
  if (to) return {Ray3(o + dir * FT(ray.tmax), -dir)};
  // A line as its two rays from the origin: CGAL 5.5's Line_3 / Iso_cuboid_3 test answers hit
  // for a line parallel to a slab that lies in the slab's boundary plane, wherever the other
  // two slabs are (it compares their parameters as ratios over the parallel slab's 0 / 0).
  return {Ray3(o, dir), Ray3(o, -dir)};
}

/// The ray's points against the box, a direction component whose reciprocal overflows being 0
/// (parallel to its slab, by the contract of intersect_ray_aabb).
bool ray_meets(Ray ray, const Cuboid& box) {
  for (int k = 0; k < 3; ++k) {
    if (ray.dir[k] != 0 && std::isinf(1.0 / ray.dir[k])) ray.dir[k] = 0;
  }
  for (const RayPart& part : ray_parts(ray)) {
    if (std::visit([&box](const auto& x) { return CGAL::do_intersect(x, box); }, part)) return true;
  }
  return false;
}

/// The parameter t of the point p of the line origin + t dir (dir not 0).
FT parameter(const Point& p, const Point& origin, const Vector& dir) { return (p - origin) * dir / (dir * dir); }

/// The least parameter over the points where a part of a ray and a piece of a face meet (their
/// intersection is a point or a segment), if they meet.
template <class Part, class Face>
std::optional<FT> first_meeting(const Part& part, const Face& face, const Point& origin, const Vector& dir) {
  if (!meet(part, face)) return std::nullopt;
  if constexpr (std::is_same_v<Part, Point>) {
    return parameter(part, origin, dir);
  } else if constexpr (std::is_same_v<Face, Point>) {
    return parameter(face, origin, dir);
  } else {
    const auto where = CGAL::intersection(part, face);
    if (!where) throw std::logic_error("cgal_answer: CGAL's do_intersect and intersection disagree");
    if (const Point* p = boost::get<Point>(&*where)) return parameter(*p, origin, dir);
    const Segment& s = boost::get<Segment>(*where);
    return std::min(parameter(s.source(), origin, dir), parameter(s.target(), origin, dir));
  }
}

/// The largest double <= t and the smallest double >= t: from a double next to t's exact value,
/// down while above t, then up while the next double is still <= t. (Not from t's lazy
/// approximation: its interval may be wide, even unbounded, and the steps countless.)
Bracket bracket(const FT& t) {
  constexpr double kMax = std::numeric_limits<double>::max();
  double down = std::clamp(CGAL::to_double(CGAL::exact(t)), -kMax, kMax);
  while (down != -INFINITY && FT(down) > t) down = std::nextafter(down, -INFINITY);
  while (down != kMax && FT(std::nextafter(down, INFINITY)) <= t) down = std::nextafter(down, INFINITY);
  down += 0.0;  // -0 as 0
  const bool is_double = down != -INFINITY && FT(down) == t;
  return {down, is_double ? down : std::nextafter(down, INFINITY)};
}

/// The corners of the intersection of two pieces of triangles that meet (a point, a segment, a
/// triangle or a convex polygon as CGAL::intersection gives it).
template <class X, class Y>
std::vector<Point> corners_of(const X& x, const Y& y) {
  if constexpr (std::is_same_v<X, Point>) {
    return {x};
  } else if constexpr (std::is_same_v<Y, Point>) {
    return {y};
  } else if constexpr (std::is_same_v<X, Tetrahedron> || std::is_same_v<Y, Tetrahedron>) {
    throw std::logic_error("corners_of: a triangle has no tetrahedron piece");
  } else {
    const auto where = CGAL::intersection(x, y);
    if (!where) throw std::logic_error("cgal_answer: CGAL's do_intersect and intersection disagree");
    if (const Point* p = boost::get<Point>(&*where)) return {*p};
    if (const Segment* s = boost::get<Segment>(&*where)) return {s->source(), s->target()};
    if constexpr (std::is_same_v<X, Triangle3> && std::is_same_v<Y, Triangle3>) {
      if (const Triangle3* t = boost::get<Triangle3>(&*where)) return {t->vertex(0), t->vertex(1), t->vertex(2)};
      return boost::get<std::vector<Point>>(*where);
    }
    throw std::logic_error("corners_of: an intersection of unexpected type");
  }
}

/// A hit or a miss, with nothing more.
CgalAnswer hit_or_miss(bool hit) {
  CgalAnswer answer;
  answer.hit = hit;
  return answer;
}

}  // namespace

CgalAnswer cgal_answer(const Sphere& a, const Sphere& b) {
  require_finite({a.center, b.center, {a.radius, b.radius, 0}});
  require(a.radius >= 0 && b.radius >= 0, "negative radius");
  const FT reach = FT(a.radius) + FT(b.radius);
  const int sign = CGAL::sign(reach * reach - CGAL::squared_distance(point(a.center), point(b.center)));
  CgalAnswer answer = hit_or_miss(sign >= 0);
  answer.margin_sign = sign;
  answer.distance_down = exact::signed_distance_down(1, CGAL::squared_distance(point(a.center), point(b.center)), reach,
                                                     [](const FT& t) { return CGAL::to_double(CGAL::exact(t)); });
  return answer;
}

CgalAnswer cgal_answer(const Sphere& ball, const Obb& box) {
  require_finite({ball.center, {ball.radius, 0, 0}});
  require(ball.radius >= 0, "negative radius");
  const Point c = point(ball.center);
  // The centre's squared distance to the box: the least over its pieces, 0 in one.
  std::optional<FT> outside;
  for (const Piece& piece : pieces(box)) {
    const FT d = std::visit([&c](const auto& s) { return CGAL::squared_distance(c, s); }, piece);
    if (!outside || d < *outside) outside = d;
  }
  // In the box: its squared distance to the boundary, the least over the planes of the six faces
  // (each through three corners); 0 for a flat box, which is all boundary.
  FT depth = 0;
  bool solid = true;
  for (int i = 0; i < 3; ++i) solid = solid && box.half[i] > 0;
  if (*outside == 0 && solid) {
    std::optional<FT> least;
    const Vector half_axis[3] = {vector(box.axes.col[0]) * FT(box.half[0]), vector(box.axes.col[1]) * FT(box.half[1]),
                                 vector(box.axes.col[2]) * FT(box.half[2])};
    for (int i = 0; i < 3; ++i) {
      const Vector &u = half_axis[(i + 1) % 3], &w = half_axis[(i + 2) % 3];
      for (int side : {1, -1}) {
        const Point face = point(box.center) + half_axis[i] * FT(side);
        const FT d = CGAL::squared_distance(c, K::Plane_3(face + u + w, face - u + w, face + u - w));
        if (!least || d < *least) least = d;
      }
    }
    depth = *least;
  }
  const bool inside = *outside == 0;
  const FT squared = inside ? depth : *outside, reach(ball.radius);
  CgalAnswer answer = hit_or_miss(inside || squared <= reach * reach);
  answer.margin_sign = inside ? (squared > 0 || reach > 0 ? 1 : 0) : CGAL::sign(reach * reach - squared);
  answer.distance_down = exact::signed_distance_down(inside ? -1 : 1, squared, reach,
                                                     [](const FT& t) { return CGAL::to_double(CGAL::exact(t)); });
  return answer;
}

CgalAnswer cgal_answer(const Aabb& a, const Aabb& b) { return hit_or_miss(CGAL::do_intersect(cuboid(a), cuboid(b))); }
CgalAnswer cgal_answer(const Ray& ray, const Aabb& box) { return hit_or_miss(ray_meets(ray, cuboid(box))); }
CgalAnswer cgal_answer(const Triangle& tri, const Aabb& box) { return hit_or_miss(meet(pieces(tri), cuboid(box))); }
/// The squared distance between two pieces of triangles (points, segments, triangles).
template <class X, class Y>
FT squared_distance_between(const X& x, const Y& y) {
  if constexpr (std::is_same_v<X, Tetrahedron> || std::is_same_v<Y, Tetrahedron>) {
    throw std::logic_error("squared_distance_between: a triangle has no tetrahedron piece");
  } else if constexpr (std::is_same_v<X, Triangle3> && std::is_same_v<Y, Segment>) {
    return squared_distance_between(y, x);
  } else if constexpr (std::is_same_v<X, Segment> && std::is_same_v<Y, Triangle3>) {
    if (CGAL::do_intersect(x, y)) return 0;
    FT least = std::min(CGAL::squared_distance(x.source(), y), CGAL::squared_distance(x.target(), y));
    for (int i = 0; i < 3; ++i) least = std::min(least, CGAL::squared_distance(x, Segment(y.vertex(i), y.vertex((i + 1) % 3))));
    return least;
  } else {
    return CGAL::squared_distance(x, y);
  }
}

CgalAnswer cgal_answer(const Triangle& a, const Triangle& b) {
  const Piece pa = pieces(a)[0], pb = pieces(b)[0];
  CgalAnswer answer = hit_or_miss(std::visit([](const auto& x, const auto& y) { return meet(x, y); }, pa, pb));
  answer.distance_down = exact::root_down(
      std::visit([](const auto& x, const auto& y) { return squared_distance_between(x, y); }, pa, pb),
      [](const FT& t) { return CGAL::to_double(CGAL::exact(t)); });
  if (answer.hit) {
    for (const Point& p : std::visit([](const auto& x, const auto& y) { return corners_of(x, y); }, pa, pb)) {
      answer.corners.push_back({bracket(p.x()), bracket(p.y()), bracket(p.z())});
    }
  }
  return answer;
}
namespace {

/// A box's boundary as pieces: its six faces, two triangles each; a flat box, a segment or a point
/// is all boundary, its pieces themselves.
Pieces boundary(const Obb& b) {
  Pieces solid = pieces(b);
  if (!std::holds_alternative<Tetrahedron>(solid.front())) return solid;
  const Point c = point(b.center);
  Vector e[3];
  for (int i = 0; i < 3; ++i) e[i] = vector(b.axes.col[i]) * FT(b.half[i]);
  Pieces faces;
  for (int i = 0; i < 3; ++i) {
    const Vector &u = e[(i + 1) % 3], &w = e[(i + 2) % 3];
    for (const FT& side : {FT(1), FT(-1)}) {
      const Point f = c + e[i] * side;
      faces.push_back(Triangle3(f - u - w, f + u - w, f + u + w));
      faces.push_back(Triangle3(f - u - w, f + u + w, f - u + w));
    }
  }
  return faces;
}

/// The eight corners of a box (repeated where half extents are 0).
std::vector<Point> box_corners(const Obb& b) {
  std::vector<Point> out;
  for (int bits = 0; bits < 8; ++bits) {
    Point p = point(b.center);
    for (int i = 0; i < 3; ++i) p = p + vector(b.axes.col[i]) * FT((bits >> i & 1) ? b.half[i] : -b.half[i]);
    out.push_back(p);
  }
  return out;
}

/// The squared penetration depth of two convex polytopes that meet, given by their corners: the
/// least squared distance from the origin to the planes of the faces of CGAL's convex hull
/// (convex_hull_3) of their Minkowski difference; 0 where that difference is flat (no translation
/// is needed to leave a set with no inside).
FT squared_depth(const std::vector<Point>& a, const std::vector<Point>& b) {
  std::vector<Point> m;
  for (const Point& p : a) {
    for (const Point& q : b) m.push_back(CGAL::ORIGIN + (p - q));
  }
  std::size_t i1 = 1, i2 = 0, i3 = 0;
  while (i1 < m.size() && m[i1] == m[0]) ++i1;
  for (i2 = i1 + 1; i1 < m.size() && i2 < m.size() && CGAL::collinear(m[0], m[i1], m[i2]); ++i2) {
  }
  for (i3 = i2 + 1; i2 < m.size() && i3 < m.size() && CGAL::coplanar(m[0], m[i1], m[i2], m[i3]); ++i3) {
  }
  if (i3 >= m.size()) return 0;
  CGAL::Polyhedron_3<K> hull;
  CGAL::convex_hull_3(m.begin(), m.end(), hull);
  std::optional<FT> least;
  for (auto f = hull.facets_begin(); f != hull.facets_end(); ++f) {
    const auto h = f->halfedge();
    const K::Plane_3 plane(h->vertex()->point(), h->next()->vertex()->point(), h->next()->next()->vertex()->point());
    const FT d = CGAL::squared_distance(Point(CGAL::ORIGIN), plane);
    if (!least || d < *least) least = d;
  }
  return *least;
}

/// The least squared distance between two sets of pieces (each non-empty).
FT least_squared_distance(const Pieces& a, const Pieces& b) {
  std::optional<FT> least;
  for (const Piece& x : a) {
    for (const Piece& y : b) {
      const FT d = std::visit([](const auto& p, const auto& q) { return squared_distance_between(p, q); }, x, y);
      if (!least || d < *least) least = d;
    }
  }
  return *least;
}

}  // namespace

CgalAnswer cgal_answer(const Obb& a, const Obb& b) {
  CgalAnswer answer = hit_or_miss(meet(pieces(a), pieces(b)));
  const auto to_double = [](const FT& t) { return CGAL::to_double(CGAL::exact(t)); };
  if (answer.hit) {
    answer.distance_down = exact::signed_distance_down(-1, squared_depth(box_corners(a), box_corners(b)), FT(0), to_double);
    return answer;
  }
  answer.distance_down = exact::signed_distance_down(1, least_squared_distance(boundary(a), boundary(b)), FT(0), to_double);
  return answer;
}

CgalAnswer cgal_answer(const Triangle& tri, const Obb& box) {
  const Pieces t = pieces(tri);
  CgalAnswer answer = hit_or_miss(meet(t, pieces(box)));
  const auto to_double = [](const FT& x) { return CGAL::to_double(CGAL::exact(x)); };
  if (answer.hit) {
    const std::vector<Point> corners{point(tri.v[0]), point(tri.v[1]), point(tri.v[2])};
    answer.distance_down = exact::signed_distance_down(-1, squared_depth(corners, box_corners(box)), FT(0), to_double);
    return answer;
  }
  answer.distance_down = exact::signed_distance_down(1, least_squared_distance(t, boundary(box)), FT(0), to_double);
  return answer;
}

CgalAnswer cgal_answer(int k, const std::vector<Vec3>& a_points, const std::vector<Vec3>& b_points) {
  const std::span<const KdopDirection> directions = kdop_directions(k);
  require(!directions.empty(), "no direction set for this k");
  for (const Vec3& p : a_points) require_finite({p});
  for (const Vec3& p : b_points) require_finite({p});
  CgalAnswer answer;
  for (const KdopDirection& d : directions) {
    const Vector n(FT(d.x), FT(d.y), FT(d.z));
    // The slab [lo, hi] of the set's exact k-DOP along n; none for an empty set.
    const auto slab = [&n](const std::vector<Vec3>& points) -> std::optional<std::pair<FT, FT>> {
      if (points.empty()) return std::nullopt;
      FT lo = n * (point(points[0]) - CGAL::ORIGIN), hi = lo;
      for (const Vec3& p : points) {
        const FT s = n * (point(p) - CGAL::ORIGIN);
        if (s < lo) lo = s;
        if (s > hi) hi = s;
      }
      return std::pair{lo, hi};
    };
    const auto a = slab(a_points), b = slab(b_points);
    const int sign = a && b ? CGAL::sign(std::min(a->second, b->second) - std::max(a->first, b->first)) : -1;
    answer.slab_signs.push_back(sign);
  }
  answer.margin_sign = *std::min_element(answer.slab_signs.begin(), answer.slab_signs.end());
  answer.hit = *answer.margin_sign >= 0;
  return answer;
}

CgalAnswer cgal_answer(const Ray& ray, const harness::MeshRef& mesh_ref, const harness::LibraryBvh&) {
  require(mesh_ref.mesh != nullptr, "no mesh");
  const Mesh& mesh = *mesh_ref.mesh;
  require(!mesh_problem(mesh), "invalid mesh");
  const std::vector<RayPart> parts = ray_parts(ray);
  const Point origin = point(ray.origin);
  const Vector dir = vector(ray.dir);
  const bool origin_alone = dir == CGAL::NULL_VECTOR;  // t stands for tmin
  CgalAnswer answer;
  std::vector<std::uint32_t> faces;
  std::optional<FT> first;
  for (std::uint32_t f = 0; f < mesh.size(); ++f) {
    bool met = false;
    for (const Piece& piece : pieces(mesh.triangle(f))) {
      for (const RayPart& part : parts) {
        std::visit(
            [&](const auto& x, const auto& y) {
              if constexpr (!std::is_same_v<std::decay_t<decltype(y)>, Tetrahedron>) {  // not of a face
                if (origin_alone) {
                  met |= meet(x, y);
                } else if (const std::optional<FT> t = first_meeting(x, y, origin, dir)) {
                  met = true;
                  if (!first || *t < *first) first = t;
                }
              }
            },
            part, piece);
      }
    }
    if (met) faces.push_back(f);
  }
  answer.hit = !faces.empty();
  answer.faces = std::move(faces);
  if (answer.hit) answer.first_t = origin_alone ? Bracket{ray.tmin, ray.tmin} : bracket(*first);
  return answer;
}

namespace {

/// A mesh's faces, each vertex placed exactly by the pose, as pieces, with boxes holding them.
struct PlacedFaces {
  std::vector<Piece> faces;
  std::vector<CGAL::Bbox_3> boxes;
};

PlacedFaces placed_faces(const harness::MeshRef& ref, const RigidTransform& pose) {
  require(ref.mesh != nullptr, "no mesh");
  const Mesh& mesh = *ref.mesh;
  require(!mesh_problem(mesh), "invalid mesh");
  require(finite(pose.rotation) && finite(pose.translation), "a pose has a NaN or infinite entry");
  std::vector<Point> vertices;
  for (const Vec3& v : mesh.vertices) {
    require_finite({v});
    FT c[3];
    for (int i = 0; i < 3; ++i) {
      const Vec3 r = pose.rotation.row(i);
      c[i] = FT(r.x) * FT(v.x) + FT(r.y) * FT(v.y) + FT(r.z) * FT(v.z) + FT(pose.translation[i]);
    }
    vertices.emplace_back(c[0], c[1], c[2]);
  }
  PlacedFaces out;
  for (std::size_t f = 0; f < mesh.size(); ++f) {
    const std::array<Point, 3> p = {vertices[mesh.faces[f][0]], vertices[mesh.faces[f][1]], vertices[mesh.faces[f][2]]};
    out.faces.push_back(triangle_piece(p));
    out.boxes.push_back(p[0].bbox() + p[1].bbox() + p[2].bbox());
  }
  return out;
}

/// A lower bound on the squared distance between the points of two boxes: the gaps along the
/// axes squared and summed in doubles (each step within an ulp, 5 ulps in all), less 2^-49 of it.
double squared_gap_down(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double gap = std::max({0.0, b.min(k) - a.max(k), a.min(k) - b.max(k)});
    sum += gap * gap;
  }
  return sum * (1 - 0x1p-49);
}

bool boxes_meet(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.max(k) < b.min(k) || b.max(k) < a.min(k)) return false;
  }
  return true;
}

}  // namespace

CgalAnswer cgal_answer(const harness::MeshPair& meshes) {
  const PlacedFaces a = placed_faces(meshes.a, meshes.pose_a), b = placed_faces(meshes.b, meshes.pose_b);
  std::vector<harness::FacePair> met;
  for (std::uint32_t i = 0; i < a.faces.size(); ++i) {
    for (std::uint32_t j = 0; j < b.faces.size(); ++j) {
      if (!boxes_meet(a.boxes[i], b.boxes[j])) continue;
      if (std::visit([](const auto& x, const auto& y) { return meet(x, y); }, a.faces[i], b.faces[j])) met.emplace_back(i, j);
    }
  }
  CgalAnswer answer = hit_or_miss(!met.empty());
  answer.pairs = std::move(met);
  if (a.faces.empty() || b.faces.empty()) return answer;
  const auto to_double = [](const FT& t) { return CGAL::to_double(CGAL::exact(t)); };
  if (answer.hit) {
    answer.distance_down = 0;
    return answer;
  }
  // Apart: every pair in the order of its boxes' gap, until the gap exceeds the least distance.
  struct Candidate {
    double gap_down;
    std::uint32_t i, j;
  };
  std::vector<Candidate> order;
  order.reserve(a.faces.size() * b.faces.size());
  for (std::uint32_t i = 0; i < a.faces.size(); ++i) {
    for (std::uint32_t j = 0; j < b.faces.size(); ++j) order.push_back({squared_gap_down(a.boxes[i], b.boxes[j]), i, j});
  }
  std::sort(order.begin(), order.end(), [](const Candidate& x, const Candidate& y) { return x.gap_down < y.gap_down; });
  std::optional<FT> least;
  double least_up = INFINITY;  // a double >= *least
  for (const Candidate& c : order) {
    if (c.gap_down > least_up) break;
    const FT d = std::visit([](const auto& x, const auto& y) { return squared_distance_between(x, y); }, a.faces[c.i],
                            b.faces[c.j]);
    if (!least || d < *least) {
      least = d;
      least_up = CGAL::to_interval(d).second;
    }
  }
  answer.distance_down = exact::root_down(*least, to_double);
  return answer;
}

CgalAnswer cgal_answer(const Disc& disc, const std::vector<Wall>& walls) {
  require(std::isfinite(disc.center.x) && std::isfinite(disc.center.y) && std::isfinite(disc.radius), "a coordinate is NaN or infinite");
  require(disc.radius >= 0, "negative radius");
  const K::Point_2 centre(disc.center.x, disc.center.y);
  const FT reach2 = FT(disc.radius) * FT(disc.radius);
  std::vector<std::uint32_t> touched;
  for (std::uint32_t i = 0; i < walls.size(); ++i) {
    const Wall& w = walls[i];
    if (!std::isfinite(w.a.x) || !std::isfinite(w.a.y) || !std::isfinite(w.b.x) || !std::isfinite(w.b.y)) continue;
    const K::Point_2 a(w.a.x, w.a.y), b(w.b.x, w.b.y);
    const FT distance2 = a == b ? CGAL::squared_distance(centre, a) : CGAL::squared_distance(centre, K::Segment_2(a, b));
    if (distance2 <= reach2) touched.push_back(i);
  }
  CgalAnswer answer = hit_or_miss(!touched.empty());
  answer.faces = std::move(touched);
  return answer;
}

}  // namespace cc::cgal
