// Triangle meshes: an indexed triangle list, the input of the bounding-volume hierarchies.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "collide/triangle.h"

namespace cc {

/// A triangle soup or an indexed mesh: faces[i] names three entries of vertices. Nothing is
/// assumed about connectivity or orientation; degenerate faces (repeated or collinear vertices)
/// are valid and collide as the segments or points they are.
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> faces;

  std::size_t size() const { return faces.size(); }
  Triangle triangle(std::size_t face) const {
    const auto& f = faces[face];
    return {{vertices[f[0]], vertices[f[1]], vertices[f[2]]}};
  }
  friend bool operator==(const Mesh&, const Mesh&) = default;
};

/// Why the mesh cannot be used (a face naming a missing vertex, a NaN or infinite coordinate),
/// naming the first offending face or vertex by its 0-based index; nothing when it is valid.
/// Hierarchies are built only over valid meshes.
std::optional<std::string> mesh_problem(const Mesh& mesh);

/// The mesh made of the given faces of `mesh` (in that order), with only the vertices they use.
Mesh submesh(const Mesh& mesh, const std::vector<std::uint32_t>& faces);

}  // namespace cc
