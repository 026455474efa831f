#include "collide/mesh.h"

#include <unordered_map>

namespace cc {

std::optional<std::string> mesh_problem(const Mesh& mesh) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!finite(mesh.vertices[v])) return "vertex " + std::to_string(v) + " has a NaN or infinite coordinate";
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (std::uint32_t index : mesh.faces[f]) {
      if (index >= mesh.vertices.size()) {
        return "face " + std::to_string(f) + " names vertex " + std::to_string(index) + " of " +
               std::to_string(mesh.vertices.size());
      }
    }
  }
  return std::nullopt;
}

Mesh submesh(const Mesh& mesh, const std::vector<std::uint32_t>& faces) {
  Mesh out;
  std::unordered_map<std::uint32_t, std::uint32_t> renumbered;
  for (std::uint32_t f : faces) {
    std::array<std::uint32_t, 3> face{};
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t old = mesh.faces[f][i];
      auto [it, fresh] = renumbered.try_emplace(old, static_cast<std::uint32_t>(out.vertices.size()));
      if (fresh) out.vertices.push_back(mesh.vertices[old]);
      face[i] = it->second;
    }
    out.faces.push_back(face);
  }
  return out;
}

}  // namespace cc
