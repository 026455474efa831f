// Meshes made from a seed (a sphere, a torus, a terrain, a plate, a soup with segments and points):
// for scale, for shapes a user's own meshes lack, and for the harness's mesh cases, whose case
// files name a recipe.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "collide/mesh.h"

namespace cc {

/// A recipe for a mesh. The same recipe gives the same mesh bit for bit on any machine with
/// the same libm (the sphere and the torus use sin and cos).
struct ProceduralMesh {
  enum class Shape {
    sphere,   // a UV sphere
    torus,    // a ring torus
    terrain,  // a height field over a square grid
    plate,    // a thin box: a rectangle of the given thickness (0: a flat, two-sided rectangle)
    soup,     // random triangles, large and small: centres in the cube of half side size, corners within 2 size
  };
  Shape shape = Shape::sphere;
  std::uint64_t seed = 0;
  int resolution = 8;      // grid cells per side (triangles grow as its square); soup: triangles
  double size = 1;         // radius, half side, or half extent of the cube
  double thickness = 0;    // plate only
  int degenerate_percent = 0;  // faces replaced by a segment or a point of the same face
  friend bool operator==(const ProceduralMesh&, const ProceduralMesh&) = default;
};

std::string_view to_string(ProceduralMesh::Shape shape);
std::optional<ProceduralMesh::Shape> shape_named(std::string_view name);

/// The mesh of a recipe: a triangle soup (three fresh vertices per face, as in FCL's meshes),
/// centred on the origin. resolution is clamped to [1, 200].
Mesh make_mesh(const ProceduralMesh& recipe);

}  // namespace cc
