#include "collide/mesh.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc {
namespace {

Mesh two_triangles() {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.faces = {{0, 1, 2}, {1, 3, 2}};
  return m;
}

TEST(Mesh, TriangleGathersItsVertices) {
  const Mesh m = two_triangles();
  EXPECT_EQ(m.triangle(1), (Triangle{{Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}}}));
}

TEST(Mesh, ProblemsNameTheFaceOrVertex) {
  Mesh m = two_triangles();
  EXPECT_FALSE(mesh_problem(m));
  m.faces.push_back({0, 1, 4});
  EXPECT_EQ(mesh_problem(m), "face 2 names vertex 4 of 4");
  m = two_triangles();
  m.vertices[3].y = NAN;
  EXPECT_EQ(mesh_problem(m), "vertex 3 has a NaN or infinite coordinate");
}

TEST(Mesh, SubmeshKeepsOnlyTheVerticesItUses) {
  const Mesh s = submesh(two_triangles(), {1});
  EXPECT_EQ(s.vertices.size(), 3u);
  EXPECT_EQ(s.triangle(0), two_triangles().triangle(1));
  EXPECT_EQ(submesh(two_triangles(), {}).size(), 0u);
}

}  // namespace
}  // namespace cc
