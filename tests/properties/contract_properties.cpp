// The library's set-theoretic contracts against their definitions in exact arithmetic, through
// its public headers only:
//  - convex_hull: the extremes of linear functions over the points (along the 13 directions of
//    the 26-DOP, the points' differences and the normals of their planes) are reached at its
//    vertices, so the extreme points are among them; coincident points give one vertex;
//  - fit_obb: every point lies in the box, whose axes are right-handed and orthonormal to
//    within the OBB contract's tolerance; the merge of two boxes holds both;
//  - kdop_cone, support_bound: the cone's nonnegative combination is its direction to within
//    2^-46 of it, and the bound is at least every point's projection (up to its own rounding);
//  - rotation_radius, bounding_cube, fitted_box, mesh_ball, placed_ball: the radius is no less
//    than any vertex's distance, the ball holds every vertex, and both boxes, the placed ball and
//    its cube hold the mesh placed by the pose, exactly and as apply() places it;
//  - transform_error_bound: apply() places each vertex within it of the exact placement.
// The point sets are coincident, collinear, coplanar or in general position, in a random order
// (the extremes anywhere), with repeated points, at every scale the value source draws.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>

#include "collide/bounding_volume.h"
#include "collide/convex_hull.h"
#include "collide/kdop.h"
#include "collide/kdop_support.h"
#include "collide/obb_fit.h"
#include "collide/object_bounds.h"
#include "harness/formats/number_text.h"
#include "harness/generation/rotation.h"
#include "harness/generation/values.h"
#include "oracle/exact/rational.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using exact::QVec3;
using exact::Rational;
using exact::rational;

enum class Layout { coincident, collinear, coplanar, general };
constexpr Layout kLayouts[] = {Layout::coincident, Layout::collinear, Layout::coplanar, Layout::general};
const char* to_string(Layout l) {
  switch (l) {
    case Layout::coincident: return "coincident";
    case Layout::collinear: return "collinear";
    case Layout::coplanar: return "coplanar";
    case Layout::general: return "general";
  }
  return "?";
}

// How often each layout was met; each must be.
struct Layouts {
  int count[4] = {0, 0, 0, 0};
  void expect_each_met(const std::string& property) const {
    for (Layout l : kLayouts) EXPECT_GT(count[static_cast<int>(l)], 0) << property << " never met " << to_string(l) << " points";
  }
};

QVec3 q(const Vec3& v) { return rational(v); }

std::string text(const std::vector<Vec3>& points) {
  std::string out;
  for (const Vec3& p : points) {
    out += (out.empty() ? "(" : ", (") + harness::format_double(p.x) + " " + harness::format_double(p.y) + " " +
           harness::format_double(p.z) + ")";
  }
  return out;
}
QVec3 q(const KdopDirection& d) { return {d.x, d.y, d.z}; }

// The layout of points, decided exactly: the rank of their differences.
Layout layout_of(const std::vector<Vec3>& points) {
  std::vector<QVec3> d;
  for (const Vec3& p : points) d.push_back(q(p) - q(points[0]));
  const auto nonzero = std::find_if(d.begin(), d.end(), [](const QVec3& v) { return !exact::is_zero(v); });
  if (nonzero == d.end()) return Layout::coincident;
  const auto cross_nonzero = std::find_if(d.begin(), d.end(), [&](const QVec3& v) { return !exact::is_zero(cross(*nonzero, v)); });
  if (cross_nonzero == d.end()) return Layout::collinear;
  const QVec3 n = cross(*nonzero, *cross_nonzero);
  for (const QVec3& v : d) {
    if (sgn(dot(n, v)) != 0) return Layout::general;
  }
  return Layout::coplanar;
}

// Points in the layout asked for, from a base point and directions the value source draws, with
// small integer and half coefficients (so they are exact), some repeated, shuffled.
std::vector<Vec3> draw_points(harness::ValueSource& values, Layout layout) {
  harness::Choices& c = values.choices();
  const Vec3 base = values.point();
  const Vec3 u = values.point(), v = values.point();
  const std::size_t n = 1 + c.draw(10);
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < n; ++i) {
    if (!points.empty() && c.chance(15)) {
      points.push_back(points[c.draw(points.size())]);
      continue;
    }
    const double a = values.small_int(8) * (c.chance(30) ? 0.5 : 1.0), b = values.small_int(8);
    switch (layout) {
      case Layout::coincident: points.push_back(base); break;
      case Layout::collinear: points.push_back(base + a * u); break;
      case Layout::coplanar: points.push_back(base + a * u + b * v); break;
      case Layout::general: points.push_back(c.chance(70) ? values.point() : base + a * u + b * v); break;
    }
  }
  for (std::size_t i = points.size(); i > 1; --i) std::swap(points[i - 1], points[c.draw(i)]);  // extremes anywhere
  return points;
}

// Directions to try linear functions along: the 13 of the 26-DOP, and the points' differences
// and their cross products (the normals of the point set's planes).
std::vector<QVec3> directions(const std::vector<Vec3>& points) {
  std::vector<QVec3> out;
  for (const KdopDirection& d : kdop_directions<26>()) out.push_back(q(d));
  for (std::size_t i = 1; i < points.size() && i < 5; ++i) {
    out.push_back(q(points[i]) - q(points[0]));
    for (std::size_t j = 1; j < i; ++j) out.push_back(cross(q(points[i]) - q(points[0]), q(points[j]) - q(points[0])));
  }
  return out;
}

TEST(Contracts, AConvexHullReachesEveryExtremeAtItsVertices) {
  Layouts met;
  const std::string property = "convex_hull's vertices and triangles";
  const bool passed = check_property_with_choices(property, 1500, [&](harness::Choices& c) {
    harness::ValueSource values(c, {.max_exponent = 8, .extreme = true, .huge = true});
    const Layout layout = kLayouts[c.draw(4)];
    const std::vector<Vec3> points = draw_points(values, layout);
    const Layout actual = layout_of(points);
    ++met.count[static_cast<int>(actual)];
    const ConvexHull hull = convex_hull(points);
    std::vector<QVec3> all, at_vertices;
    for (const Vec3& p : points) all.push_back(q(p));
    for (std::uint32_t i : hull.vertices) {
      RC_ASSERT(i < points.size());
      at_vertices.push_back(q(points[i]));
    }
    RC_ASSERT(!at_vertices.empty());
    for (const QVec3& d : directions(points)) {
      for (int sign : {1, -1}) {
        Rational best = sign * dot(d, all[0]), best_at_vertex = sign * dot(d, at_vertices[0]);
        for (const QVec3& p : all) best = std::max(best, Rational(sign * dot(d, p)));
        for (const QVec3& p : at_vertices) best_at_vertex = std::max(best_at_vertex, Rational(sign * dot(d, p)));
        if (best != best_at_vertex) {
          RC_FAIL(std::string(to_string(actual)) + " points: an extreme along a direction is not at a vertex (" +
                  std::to_string(hull.vertices.size()) + " vertices of " + std::to_string(points.size()) + " points): " +
                  text(points));
        }
      }
    }
    if (actual == Layout::coincident) RC_ASSERT(hull.vertices.size() == 1u);
    if (actual == Layout::coincident || actual == Layout::collinear) RC_ASSERT(hull.triangles.empty());
    // Triangles of indices among the vertices. (Whether each lies exactly in a supporting plane
    // is not checked: Qhull computes the facets in floating point, and a set flat to within a
    // few subnormals gets facets that cut it by as much, or none.)
    for (const auto& t : hull.triangles) {
      for (std::uint32_t i : t) RC_ASSERT(std::find(hull.vertices.begin(), hull.vertices.end(), i) != hull.vertices.end());
    }
  });
  EXPECT_TRUE(passed);
  met.expect_each_met(property);
}

// A box holds what projects onto each of its axes within its half extent of its centre's
// projection (as the separating-axis tests see it).
bool holds(const Obb& b, const QVec3& p) {
  const QVec3 d = p - q(b.center);
  for (int k = 0; k < 3; ++k) {
    if (abs(dot(q(b.axes.col[k]), d)) > rational(b.half[k])) return false;
  }
  return true;
}

TEST(Contracts, AFittedObbHoldsItsPointsWithOrthonormalAxes) {
  Layouts met;
  const std::string property = "fit_obb holds its points";
  const bool passed = check_property_with_choices(property, 800, [&](harness::Choices& c) {
    harness::ValueSource values(c, {.max_exponent = 8, .extreme = true, .huge = true});
    const std::vector<Vec3> points = draw_points(values, kLayouts[c.draw(4)]);
    ++met.count[static_cast<int>(layout_of(points))];
    const Obb box = fit_obb(points);
    for (const Vec3& p : points) {
      if (!holds(box, q(p))) RC_FAIL("a point lies outside its fitted box: " + text(points));
    }
    // The header promises 2^-50, "well within" the OBB contract's tolerance; (0, 1, 2), (0, 0, 0)
    // gets an axis of length 1 + 2^-51 (2^-50 + 2^-102 off): checked against the contract's.
    const Rational tolerance = rational(kObbOrthonormalTolerance);
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) {
        Rational g = dot(q(box.axes.col[i]), q(box.axes.col[j]));
        if (i == j) g -= 1;
        if (abs(g) > tolerance) RC_FAIL("the axes are not orthonormal to within 2^-48: " + text(points));
      }
    }
    if (sgn(dot(cross(q(box.axes.col[0]), q(box.axes.col[1])), q(box.axes.col[2]))) <= 0) RC_FAIL("the axes are left-handed: " + text(points));
  });
  EXPECT_TRUE(passed);
  met.expect_each_met(property);
}

// The merge of two fitted boxes (the building heuristics' volume of a union) holds both boxes:
// their exact corners, center +- half_0 axis_0 +- half_1 axis_1 +- half_2 axis_2, and so (the
// merged box being an intersection of slabs) every point of either.
TEST(Contracts, AnObbMergeHoldsBothBoxes) {
  Layouts met;
  const std::string property = "the OBB merge holds both boxes";
  const bool passed = check_property_with_choices(property, 800, [&](harness::Choices& c) {
    harness::ValueSource values(c, {.max_exponent = 8, .extreme = true, .huge = true});
    const std::vector<Vec3> first = draw_points(values, kLayouts[c.draw(4)]);
    const std::vector<Vec3> second = c.chance(20) ? first : draw_points(values, kLayouts[c.draw(4)]);
    ++met.count[static_cast<int>(layout_of(second))];
    const Obb a = fit_obb(first), b = fit_obb(second);
    const Obb merged = BoundingVolume<Obb>::merge(a, b);
    for (const Obb* box : {&a, &b}) {
      for (int i = 0; i < 8; ++i) {
        QVec3 corner = q(box->center);
        for (int k = 0; k < 3; ++k) corner = corner + Rational((i >> k & 1) ? box->half[k] : -box->half[k]) * q(box->axes.col[k]);
        if (!holds(merged, corner)) RC_FAIL("a corner of a box lies outside the merge: " + text(first) + " and " + text(second));
      }
    }
  });
  EXPECT_TRUE(passed);
  met.expect_each_met(property);
}

template <int K>
QVec3 half_space_normal(int h) {
  const KdopDirection d = kdop_directions<K>()[h % (K / 2)];
  const int sign = h < K / 2 ? 1 : -1;
  return {sign * d.x, sign * d.y, sign * d.z};
}

template <int K>
void check_support(const std::vector<Vec3>& points, const Vec3& m) {
  const Kdop<K> dop = fit_kdop<K>(points);
  const KdopCone<K> cone = kdop_cone<K>(m);
  QVec3 sum{0, 0, 0};
  double reach = 0;  // sum c_j |bound_j|
  for (int j = 0; j < 3; ++j) {
    const int h = cone.normal[j];
    RC_ASSERT(cone.coefficient[j] >= 0);
    sum = sum + rational(cone.coefficient[j]) * half_space_normal<K>(h);
    reach += cone.coefficient[j] * std::fabs(h < K / 2 ? dop.hi[h] : dop.lo[h - K / 2]);
  }
  const Rational off = rational(0x1p-46 * max_abs(m));
  const QVec3 residual = q(m) - sum;
  for (int k = 0; k < 3; ++k) {
    if (abs(residual[k]) > off) RC_FAIL("k = " + std::to_string(K) + ": the cone does not combine to its direction");
  }
  double largest = 0;
  for (const Vec3& p : points) largest = std::max(largest, norm1(p));
  const Rational slack = rational(3 * 0x1p-53 * reach) + off * rational(2 * largest);
  const Rational bound = rational(support_bound(dop, cone));
  for (const Vec3& p : points) {
    if (dot(q(m), q(p)) > bound + slack) RC_FAIL("k = " + std::to_string(K) + ": a point reaches beyond the support bound");
  }
}

TEST(Contracts, TheSupportBoundOfAKdopHoldsItsPoints) {
  Layouts met;
  const std::string property = "support_bound holds the k-DOP's points";
  const bool passed = check_property_with_choices(property, 600, [&](harness::Choices& c) {
    harness::ValueSource values(c, {.max_exponent = 8, .extreme = false, .huge = false});
    const std::vector<Vec3> points = draw_points(values, kLayouts[c.draw(4)]);
    ++met.count[static_cast<int>(layout_of(points))];
    // Along a drawn direction, or the difference of two of the points (a direction in which
    // both may be extreme).
    const Vec3 m = c.chance(50) || points.size() < 2 ? values.point() : points[0] - points[points.size() - 1];
    switch (c.draw(6)) {
      case 0: check_support<6>(points, m); break;
      case 1: check_support<14>(points, m); break;
      case 2: check_support<16>(points, m); break;
      case 3: check_support<18>(points, m); break;
      case 4: check_support<24>(points, m); break;
      default: check_support<26>(points, m);
    }
  });
  EXPECT_TRUE(passed);
  met.expect_each_met(property);
}

bool holds(const Aabb& b, const QVec3& p) {
  for (int k = 0; k < 3; ++k) {
    if (p[k] < rational(b.lo[k]) || p[k] > rational(b.hi[k])) return false;
  }
  return true;
}

bool in_ball(const Sphere& s, const QVec3& p) {
  const QVec3 d = p - q(s.center);
  return dot(d, d) <= rational(s.radius) * rational(s.radius);
}

QVec3 placed_exactly(const RigidTransform& t, const Vec3& v) {
  QVec3 out = q(t.translation);
  for (int j = 0; j < 3; ++j) out = out + rational(v[j]) * q(t.rotation.col[j]);
  return out;
}

TEST(Contracts, AnObjectsBoxesHoldItsPlacedMesh) {
  Layouts met;
  const std::string property =
      "rotation_radius, bounding_cube, fitted_box and placed_ball hold the placed mesh, apply() within "
      "transform_error_bound";
  const bool passed = check_property_with_choices(property, 800, [&](harness::Choices& c) {
    harness::ValueSource values(c, {.max_exponent = 8, .extreme = true, .huge = false});
    const std::vector<Vec3> points = draw_points(values, kLayouts[c.draw(4)]);
    ++met.count[static_cast<int>(layout_of(points))];
    Mesh mesh;
    mesh.vertices = points;
    for (std::uint32_t i = 0; i + 2 < points.size(); i += 3) mesh.faces.push_back({i, i + 1, i + 2});
    const double radius = rotation_radius(mesh);
    for (const Vec3& v : points) {
      if (rational(radius) * rational(radius) < dot(q(v), q(v))) RC_FAIL("rotation_radius is below a vertex's distance: " + text(points));
    }
    const Sphere ball = mesh_ball(mesh);
    for (const Vec3& v : points) {
      if (!in_ball(ball, q(v))) RC_FAIL("mesh_ball does not hold a vertex: " + text(points));
    }
    RigidTransform pose;
    pose.translation = values.point();
    for (int rotations = 0; rotations < 3; ++rotations) {
      pose.rotation = harness::draw_rotation(values);
      const Aabb cube = bounding_cube(radius, pose), fitted = fitted_box(mesh, pose);
      const Sphere placed = placed_ball(ball, pose);
      const Aabb ball_box = box_of(placed);
      for (const Vec3& v : points) {
        const QVec3 exactly = placed_exactly(pose, v), as_applied = q(apply(pose, v));
        const Rational bound = rational(transform_error_bound(pose, norm1(v)));
        for (int k = 0; k < 3; ++k) {
          if (abs(as_applied[k] - exactly[k]) > bound) RC_FAIL("apply() places a vertex beyond transform_error_bound: " + text({v}) + " rotation " + text({pose.rotation.col[0], pose.rotation.col[1], pose.rotation.col[2]}) + " translation " + text({pose.translation}));
        }
        if (!holds(cube, exactly) || !holds(cube, as_applied)) RC_FAIL("the bounding cube does not hold a placed vertex: " + text(points) + " rotation " + text({pose.rotation.col[0], pose.rotation.col[1], pose.rotation.col[2]}) + " translation " + text({pose.translation}));
        if (!holds(fitted, exactly) || !holds(fitted, as_applied)) RC_FAIL("the fitted box does not hold a placed vertex: " + text(points) + " rotation " + text({pose.rotation.col[0], pose.rotation.col[1], pose.rotation.col[2]}) + " translation " + text({pose.translation}));
        if (!in_ball(placed, exactly) || !in_ball(placed, as_applied) || !holds(ball_box, exactly) || !holds(ball_box, as_applied)) {
          RC_FAIL("the placed ball or its cube does not hold a placed vertex: " + text(points) + " rotation " + text({pose.rotation.col[0], pose.rotation.col[1], pose.rotation.col[2]}) + " translation " + text({pose.translation}));
        }
      }
    }
  });
  EXPECT_TRUE(passed);
  met.expect_each_met(property);
}

}  // namespace
}  // namespace cc::test
