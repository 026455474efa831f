// Fitting is conservative under rounding, checked in exact arithmetic:
//  - every input point lies inside the fitted k-DOP, for every direction set;
//  - the convex hull's vertices hold every point (their hull contains it), and collinear or
//    coincident points give exactly their ends, on points in general position, on a line, in a
//    plane, on one point, and on points nudged a few ulps off a line or plane; so do the
//    vertices of fast_convex_hull (which drops only points it certifies inside).
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>

#include "collide/convex_hull.h"
#include "collide/kdop.h"
#include "harness/formats/input_json.h"
#include "harness/generation/values.h"
#include "oracle/exact/rational.h"
#include "properties/property.h"

namespace cc::test {
namespace {

template <int K>
void check_fit(const std::vector<Vec3>& points, Met& met) {
  const Kdop<K> dop = fit_kdop<K>(points);
  const auto dirs = kdop_directions<K>();
  harness::Features f;
  f.degenerate = points.size() == 1;
  for (int i = 0; i < K / 2; ++i) {
    const exact::QVec3 d{dirs[i].x, dirs[i].y, dirs[i].z};
    const bool diagonal = (dirs[i].x != 0) + (dirs[i].y != 0) + (dirs[i].z != 0) > 1;
    std::vector<exact::Rational> seen;
    for (const Vec3& p : points) {
      const exact::Rational s = dot(d, exact::rational(p));
      if (s < exact::rational(dop.lo[i]) || s > exact::rational(dop.hi[i])) {
        RC_FAIL("k = " + std::to_string(K) + ", slab " + std::to_string(i) + ": a point lies outside the fitted k-DOP");
      }
      if (diagonal && (s == exact::rational(dop.lo[i]) || s == exact::rational(dop.hi[i]))) f.touching = true;
      for (const exact::Rational& t : seen) f.parallel |= diagonal && t == s;
      seen.push_back(s);
    }
  }
  met.count(f);
}

TEST(FitKdop, EveryPointLiesInsideTheFittedKdopExactly) {
  Met met;
  const bool passed = check_property_with_choices("fit_kdop is conservative", 3000, [&](harness::Choices& c) {
    harness::ValueSource values(c, {});
    std::vector<Vec3> points;
    const auto n = 1 + c.draw(6);
    for (std::uint64_t i = 0; i < n; ++i) points.push_back(c.chance(30) && !points.empty() ? points.back() : values.point());
    switch (c.draw(6)) {
      case 0: check_fit<6>(points, met); break;
      case 1: check_fit<14>(points, met); break;
      case 2: check_fit<16>(points, met); break;
      case 3: check_fit<18>(points, met); break;
      case 4: check_fit<24>(points, met); break;
      default: check_fit<26>(points, met);
    }
  });
  EXPECT_TRUE(passed);
  expect_met_the_boundary("fit_kdop is conservative", harness::QueryKind::kdop_kdop, met);
}

// The affine hull of a point set, exactly: its dimension and a frame (origin, a direction, and
// for a plane or more a normal of the plane through origin, direction and a third point).
struct AffineHull {
  int dimension = 0;
  exact::QVec3 origin, direction, normal;
};

AffineHull affine_hull(const std::vector<exact::QVec3>& set) {
  AffineHull a;
  a.origin = set[0];
  for (const exact::QVec3& v : set) {
    const exact::QVec3 d = v - a.origin;
    if (a.dimension == 0 && !exact::is_zero(d)) a.dimension = 1, a.direction = d;
    else if (a.dimension == 1 && !exact::is_zero(exact::cross(a.direction, d))) a.dimension = 2, a.normal = exact::cross(a.direction, d);
    else if (a.dimension == 2 && sgn(exact::dot(a.normal, d)) != 0) a.dimension = 3;
  }
  return a;
}

// The convex hull of a point set (not empty), exactly, as the intersection of its affine hull
// with the inner sides of every supporting plane (in a plane: line) through points of the set;
// the facets (edges) are among them.
class ExactHull {
 public:
  explicit ExactHull(const std::vector<exact::QVec3>& set) : set_(set), affine_(affine_hull(set)) {
    const auto support = [&](const exact::QVec3& normal, const exact::QVec3& through) {
      if (exact::is_zero(normal)) return;
      int below = 0, above = 0;
      for (const exact::QVec3& v : set_) {
        const int s = sgn(exact::dot(normal, v - through));
        below += s < 0, above += s > 0;
      }
      if (below == 0) sides_.push_back({normal, through});
      if (above == 0) sides_.push_back({-1 * normal, through});
    };
    const std::size_t n = set_.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const exact::QVec3 e = set_[j] - set_[i];
        if (affine_.dimension == 1) support(e, set_[i]);
        if (affine_.dimension == 2) support(exact::cross(affine_.normal, e), set_[i]);
        for (std::size_t k = j + 1; affine_.dimension == 3 && k < n; ++k) support(exact::cross(e, set_[k] - set_[i]), set_[i]);
      }
    }
  }

  const AffineHull& affine() const { return affine_; }

  bool holds(const exact::QVec3& p) const {
    const exact::QVec3 d = p - affine_.origin;
    if (affine_.dimension == 0 && !exact::is_zero(d)) return false;
    if (affine_.dimension == 1 && !exact::is_zero(exact::cross(affine_.direction, d))) return false;
    if (affine_.dimension == 2 && sgn(exact::dot(affine_.normal, d)) != 0) return false;
    return std::all_of(sides_.begin(), sides_.end(), [&](const Side& s) { return sgn(exact::dot(s.normal, p - s.through)) >= 0; });
  }

 private:
  struct Side {
    exact::QVec3 normal, through;  // the inner side: dot(normal, p - through) >= 0
  };
  std::vector<exact::QVec3> set_;
  AffineHull affine_;
  std::vector<Side> sides_;
};

// Points that lie exactly on a point, a line, a plane or anywhere: integers (up to 2^40 for the
// base point, small ones for directions and steps) times a power of two, so every coordinate is
// a double; then, sometimes, one coordinate nudged a few ulps.
std::vector<Vec3> hull_input(harness::Choices& c, int& dimension, bool& nudged) {
  harness::ValueSource values(c, {});
  const auto n = 1 + c.draw(12);
  std::vector<Vec3> points;
  dimension = static_cast<int>(c.draw(5));
  if (dimension == 4) {  // anything: boundary-biased coordinates, repeats, ulps apart
    for (std::uint64_t i = 0; i < n; ++i) points.push_back(c.chance(20) && !points.empty() ? points[c.draw(points.size())] : values.point());
  } else {
    const auto integer = [&](int bits) {
      const auto magnitude = static_cast<double>(c.draw(std::uint64_t{1} << c.draw(static_cast<std::uint64_t>(bits) + 1)));
      return c.chance(50) ? -magnitude : magnitude;
    };
    const auto vector = [&](int bits) { return Vec3{integer(bits), integer(bits), integer(bits)}; };
    const int scale = static_cast<int>(c.draw(81)) - 40;
    const Vec3 base = vector(40);
    const Vec3 u = vector(4), v = vector(4), w = vector(4);
    for (std::uint64_t i = 0; i < n; ++i) {
      Vec3 p = base;
      if (dimension >= 1) p = p + integer(4) * u;
      if (dimension >= 2) p = p + integer(4) * v;
      if (dimension >= 3) p = p + integer(4) * w;
      points.push_back({std::ldexp(p.x, scale), std::ldexp(p.y, scale), std::ldexp(p.z, scale)});
    }
  }
  nudged = c.chance(30);
  if (nudged) {
    double& x = points[c.draw(points.size())][static_cast<int>(c.draw(3))];
    x = values.nudge(x);
  }
  return points;
}

// The hull of a hull's vertices holds every point, exactly.
void expect_vertices_hold_every_point(const std::vector<Vec3>& points, const ConvexHull& hull,
                                      std::vector<exact::QVec3>& vertices) {
  std::vector<bool> seen(points.size(), false);
  vertices.clear();
  for (std::uint32_t v : hull.vertices) {
    RC_ASSERT(v < points.size());
    RC_ASSERT(!seen[v]);
    seen[v] = true;
    vertices.push_back(exact::rational(points[v]));
  }
  RC_ASSERT(!vertices.empty());
  for (const auto& t : hull.triangles) RC_ASSERT(t[0] < points.size() && t[1] < points.size() && t[2] < points.size());
  const ExactHull exact_hull(vertices);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!exact_hull.holds(exact::rational(points[i]))) RC_FAIL("point " + std::to_string(i) + " lies outside the hull of the vertices");
  }
}

TEST(ConvexHull, TheVerticesHoldEveryPointExactly) {
  std::array<int, 4> met_dimension{};
  int met_nudged_off = 0, met_undecided = 0, met_dropped = 0, cases = 0;
  const bool passed = check_property_with_choices("the convex hull holds every point", 2000, [&](harness::Choices& c) {
    int built_dimension = 0;
    bool nudged = false;
    std::vector<Vec3> points = hull_input(c, built_dimension, nudged);
    std::vector<exact::QVec3> all, vertices;
    for (const Vec3& p : points) all.push_back(exact::rational(p));
    // fast_convex_hull, on the distinct points: its vertices too hold every point.
    std::vector<Vec3> distinct = points;
    std::sort(distinct.begin(), distinct.end(), [](const Vec3& a, const Vec3& b) {
      return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
    });
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    const ConvexHull fast = fast_convex_hull(distinct);
    expect_vertices_hold_every_point(distinct, fast, vertices);
    met_dropped += fast.vertices.size() < distinct.size();
    const ConvexHull hull = convex_hull(points);
    expect_vertices_hold_every_point(points, hull, vertices);
    const AffineHull input = affine_hull(all);
    ++cases, ++met_dimension[input.dimension];
    met_nudged_off += nudged && input.dimension > std::min(built_dimension, 3);
    // Exactly the ends (the least and the greatest along the line) where collinearity is decided
    // exactly: every nonzero coordinate at least 2^-900 of the largest.
    double largest = 0, smallest = INFINITY;
    for (const Vec3& p : points) {
      for (int k = 0; k < 3; ++k) {
        largest = std::max(largest, std::fabs(p[k]));
        if (p[k] != 0) smallest = std::min(smallest, std::fabs(p[k]));
      }
    }
    const bool decided = input.dimension == 0 || smallest >= 0x1p-900 * largest;
    met_undecided += input.dimension == 1 && !decided;
    if (input.dimension <= 1 && decided) {
      RC_ASSERT(hull.triangles.empty());
      RC_ASSERT(vertices.size() == static_cast<std::size_t>(input.dimension + 1));
      if (input.dimension == 1) {
        std::vector<exact::Rational> along;
        for (const exact::QVec3& p : all) along.push_back(exact::dot(p - input.origin, input.direction));
        const auto [least, greatest] = std::minmax_element(along.begin(), along.end());
        const exact::Rational a = exact::dot(vertices[0] - input.origin, input.direction),
                              b = exact::dot(vertices[1] - input.origin, input.direction);
        RC_ASSERT(std::min(a, b) == *least);
        RC_ASSERT(std::max(a, b) == *greatest);
      }
    }
  });
  EXPECT_TRUE(passed);
  std::cout << "convex hull: " << cases << " cases; dimensions 0-3: " << met_dimension[0] << ", " << met_dimension[1]
            << ", " << met_dimension[2] << ", " << met_dimension[3] << "; nudged off their line or plane: "
            << met_nudged_off << "; collinear beyond exact decision (every point kept): " << met_undecided
            << "; fast_convex_hull dropped points: " << met_dropped << std::endl;
  for (int d = 0; d < 4; ++d) EXPECT_GT(met_dimension[d], cases / 20) << "points of dimension " << d;
  EXPECT_GT(met_nudged_off, cases / 50) << "points nudged off a point, line or plane";
  EXPECT_GT(met_dropped, cases / 20) << "fast_convex_hull never left a point out";
}

}  // namespace
}  // namespace cc::test
