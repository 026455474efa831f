// make_mesh: every shape is the same bit for bit for the same recipe (and another for another
// seed where a seed is used), has the face count its resolution gives, is valid and within its
// size of the origin; degenerate_percent makes segments and points; shape names round-trip.
#include "collide/procedural_mesh.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace cc {
namespace {

using Shape = ProceduralMesh::Shape;

constexpr Shape kAllShapes[] = {Shape::sphere, Shape::torus, Shape::terrain, Shape::plate, Shape::soup};

ProceduralMesh recipe(Shape shape, std::uint64_t seed = 1, int resolution = 8, double size = 1) {
  ProceduralMesh r;
  r.shape = shape;
  r.seed = seed;
  r.resolution = resolution;
  r.size = size;
  return r;
}

// The coordinates' bit patterns, so that -0 differs from 0.
std::vector<std::uint64_t> coordinate_bits(const Mesh& mesh) {
  std::vector<std::uint64_t> out;
  for (const Vec3& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) out.push_back(std::bit_cast<std::uint64_t>(v[k]));
  }
  return out;
}

bool is_degenerate(const Triangle& t) { return cross(t.v[1] - t.v[0], t.v[2] - t.v[0]) == Vec3{0, 0, 0}; }

std::size_t degenerate_faces(const Mesh& mesh) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < mesh.size(); ++f) n += is_degenerate(mesh.triangle(f));
  return n;
}

// Faces for a resolution n, from procedural_mesh.cpp: the sphere has n rings of 2n segments
// with one triangle per polar cell, the torus 2n x n quads, terrain n x n quads, the plate
// n x n quads a side (and a rim of 4 quads when thick), the soup n triangles.
std::size_t expected_faces(Shape shape, int n, bool thick = false) {
  switch (shape) {
    case Shape::sphere: n = std::max(n, 2); return static_cast<std::size_t>(4 * n * (n - 1));
    case Shape::torus: n = std::max(n, 3); return static_cast<std::size_t>(4 * n * n);
    case Shape::terrain: return static_cast<std::size_t>(2 * n * n);
    case Shape::plate: return static_cast<std::size_t>(4 * n * n + (thick ? 8 : 0));
    case Shape::soup: return static_cast<std::size_t>(n);
  }
  return 0;
}

TEST(ProceduralMesh, SameRecipeGivesTheSameMeshBitForBit) {
  for (Shape shape : kAllShapes) {
    ProceduralMesh r = recipe(shape, 42, 6, 2.5);
    r.thickness = 0.25;
    r.degenerate_percent = 30;
    const Mesh a = make_mesh(r);
    const Mesh b = make_mesh(r);
    EXPECT_FALSE(a.vertices.empty()) << to_string(shape);
    EXPECT_EQ(coordinate_bits(a), coordinate_bits(b)) << to_string(shape);
    EXPECT_EQ(a.faces, b.faces) << to_string(shape);
  }
}

TEST(ProceduralMesh, AnotherSeedGivesAnotherSoupAndTerrain) {
  for (Shape shape : {Shape::soup, Shape::terrain}) {
    const Mesh a = make_mesh(recipe(shape, 1));
    const Mesh b = make_mesh(recipe(shape, 2));
    EXPECT_EQ(a.size(), b.size()) << to_string(shape);
    EXPECT_NE(coordinate_bits(a), coordinate_bits(b)) << to_string(shape);
  }
}

TEST(ProceduralMesh, FaceCountFollowsTheResolution) {
  for (Shape shape : kAllShapes) {
    for (int n : {1, 2, 3, 8, 17}) {
      const Mesh mesh = make_mesh(recipe(shape, 3, n));
      EXPECT_EQ(mesh.size(), expected_faces(shape, n)) << to_string(shape) << " resolution " << n;
      EXPECT_EQ(mesh.vertices.size(), 3 * mesh.size()) << to_string(shape) << " resolution " << n;  // a soup
    }
  }
  ProceduralMesh thick = recipe(Shape::plate, 3, 5);
  thick.thickness = 0.1;
  EXPECT_EQ(make_mesh(thick).size(), expected_faces(Shape::plate, 5, true));
}

TEST(ProceduralMesh, ResolutionIsClampedToOneTo200) {
  for (Shape shape : kAllShapes) {
    EXPECT_EQ(make_mesh(recipe(shape, 3, 0)).size(), expected_faces(shape, 1)) << to_string(shape);
    EXPECT_EQ(make_mesh(recipe(shape, 3, -5)).size(), expected_faces(shape, 1)) << to_string(shape);
  }
  EXPECT_EQ(make_mesh(recipe(Shape::soup, 3, 1000)).size(), 200u);
  EXPECT_EQ(make_mesh(recipe(Shape::terrain, 3, 1000)).size(), expected_faces(Shape::terrain, 200));
}

TEST(ProceduralMesh, EveryShapeIsAValidMeshWithoutDegenerateFaces) {
  for (Shape shape : kAllShapes) {
    for (int n : {1, 8, 40}) {
      ProceduralMesh r = recipe(shape, 5, n, 3);
      if (shape == Shape::plate) r.thickness = 0.5;
      const Mesh mesh = make_mesh(r);
      EXPECT_EQ(mesh_problem(mesh), std::nullopt) << to_string(shape) << " resolution " << n;
      EXPECT_EQ(degenerate_faces(mesh), 0u) << to_string(shape) << " resolution " << n;
    }
  }
}

TEST(ProceduralMesh, SphereVerticesLieOnItsRadius) {
  const double r = 2.5;
  const Mesh mesh = make_mesh(recipe(Shape::sphere, 1, 12, r));
  for (const Vec3& v : mesh.vertices) {
    EXPECT_NEAR(std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z), r, 1e-12 * r);
  }
}

TEST(ProceduralMesh, TorusLiesWithinItsTubeAroundTheZAxis) {
  const double size = 4;
  const Mesh mesh = make_mesh(recipe(Shape::torus, 1, 10, size));
  for (const Vec3& v : mesh.vertices) {
    // Ring radius 0.7 size, tube radius 0.3 size.
    const double from_axis = std::hypot(v.x, v.y);
    EXPECT_NEAR(std::hypot(from_axis - 0.7 * size, v.z), 0.3 * size, 1e-12 * size);
  }
}

TEST(ProceduralMesh, TerrainAndPlateSpanTheirSquare) {
  const double size = 3;
  for (Shape shape : {Shape::terrain, Shape::plate}) {
    ProceduralMesh r = recipe(shape, 9, 7, size);
    r.thickness = 0.5;
    const Mesh mesh = make_mesh(r);
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const Vec3& v : mesh.vertices) {
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    }
    EXPECT_EQ(lo.x, -size) << to_string(shape);
    EXPECT_EQ(lo.y, -size) << to_string(shape);
    EXPECT_EQ(hi.x, size) << to_string(shape);
    EXPECT_EQ(hi.y, size) << to_string(shape);
    const double height = shape == Shape::terrain ? 0.2 * size : 0.25;  // terrain heights, half the thickness
    EXPECT_GE(lo.z, -height) << to_string(shape);
    EXPECT_LE(hi.z, height) << to_string(shape);
  }
}

TEST(ProceduralMesh, SoupStaysWithinTwiceItsSize) {
  // Triangle centres lie in the cube of half side `size`; corners reach at most `size` further.
  const double size = 0.75;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const Mesh mesh = make_mesh(recipe(Shape::soup, seed, 200, size));
    for (const Vec3& v : mesh.vertices) {
      for (int k = 0; k < 3; ++k) ASSERT_LE(std::fabs(v[k]), 2 * size) << "seed " << seed;
    }
  }
}

TEST(ProceduralMesh, EveryShapeIsCentredOnTheOrigin) {
  for (Shape shape : kAllShapes) {
    ProceduralMesh r = recipe(shape, 11, shape == Shape::soup ? 200 : 16, 2);
    r.thickness = 0.5;
    const Mesh mesh = make_mesh(r);
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const Vec3& v : mesh.vertices) {
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    }
    for (int k = 0; k < 3; ++k) {
      // The box around the mesh is centred on 0 (the soup's and the terrain's up to their randomness).
      const double slack = shape == Shape::soup ? 0.5 * r.size : shape == Shape::terrain && k == 2 ? 0.2 * r.size : 1e-12;
      EXPECT_NEAR(lo[k] + hi[k], 0, slack) << to_string(shape) << " axis " << k;
    }
  }
}

TEST(ProceduralMesh, ThinPlateIsFlat) {
  ProceduralMesh r = recipe(Shape::plate, 1, 6, 2);
  r.thickness = 0;
  const Mesh mesh = make_mesh(r);
  EXPECT_EQ(mesh.size(), expected_faces(Shape::plate, 6, false));  // two-sided, no rim
  for (const Vec3& v : mesh.vertices) EXPECT_EQ(v.z, 0.0);
}

TEST(ProceduralMesh, ThickPlateHasTwoFacesAtHalfItsThickness) {
  ProceduralMesh r = recipe(Shape::plate, 1, 6, 2);
  r.thickness = 0.5;
  const Mesh mesh = make_mesh(r);
  for (const Vec3& v : mesh.vertices) EXPECT_TRUE(v.z == 0.25 || v.z == -0.25) << v.z;
}

TEST(ProceduralMesh, NoDegeneratePercentGivesNoDegenerateFaces) {
  for (Shape shape : kAllShapes) {
    ProceduralMesh r = recipe(shape, 13, 10);
    r.degenerate_percent = 0;
    EXPECT_EQ(degenerate_faces(make_mesh(r)), 0u) << to_string(shape);
  }
}

TEST(ProceduralMesh, HalfDegeneratePercentGivesSomeDegenerateFaces) {
  for (Shape shape : kAllShapes) {
    ProceduralMesh r = recipe(shape, 13, 20);
    r.degenerate_percent = 50;
    const Mesh mesh = make_mesh(r);
    const std::size_t n = degenerate_faces(mesh);
    // Half the faces are replaced; two of the three replacements (a repeated vertex, a point)
    // have an exactly zero cross product, the third (a midpoint) up to rounding.
    EXPECT_GT(n, 0u) << to_string(shape);
    EXPECT_LT(n, mesh.size()) << to_string(shape);
    EXPECT_EQ(mesh_problem(mesh), std::nullopt) << to_string(shape);
  }
}

TEST(ProceduralMesh, FullDegeneratePercentMakesEveryFaceASegmentOrAPoint) {
  for (Shape shape : kAllShapes) {
    ProceduralMesh r = recipe(shape, 17, 10);
    r.degenerate_percent = 100;
    const Mesh mesh = make_mesh(r);
    for (std::size_t f = 0; f < mesh.size(); ++f) {
      const auto [a, b, c] = mesh.triangle(f).v;
      EXPECT_TRUE(c == b || c == 0.5 * (a + b)) << to_string(shape) << " face " << f;
    }
  }
}

TEST(ProceduralMesh, ShapeNamesRoundTrip) {
  for (Shape shape : kAllShapes) {
    ASSERT_TRUE(shape_named(to_string(shape)).has_value()) << to_string(shape);
    EXPECT_EQ(*shape_named(to_string(shape)), shape);
  }
  EXPECT_EQ(to_string(Shape::terrain), "terrain");
  EXPECT_EQ(shape_named("cube"), std::nullopt);
  EXPECT_EQ(shape_named("Sphere"), std::nullopt);
  EXPECT_EQ(shape_named(""), std::nullopt);
}

}  // namespace
}  // namespace cc
