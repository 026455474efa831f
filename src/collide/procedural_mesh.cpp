#include "collide/procedural_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "collide/seeded_random.h"

namespace cc {

std::string_view to_string(ProceduralMesh::Shape shape) {
  switch (shape) {
    case ProceduralMesh::Shape::sphere: return "sphere";
    case ProceduralMesh::Shape::torus: return "torus";
    case ProceduralMesh::Shape::terrain: return "terrain";
    case ProceduralMesh::Shape::plate: return "plate";
    case ProceduralMesh::Shape::soup: return "soup";
  }
  return "?";
}

std::optional<ProceduralMesh::Shape> shape_named(std::string_view name) {
  for (auto s : {ProceduralMesh::Shape::sphere, ProceduralMesh::Shape::torus, ProceduralMesh::Shape::terrain,
                 ProceduralMesh::Shape::plate, ProceduralMesh::Shape::soup}) {
    if (to_string(s) == name) return s;
  }
  return std::nullopt;
}

namespace {

using Random = SeededRandom;

class Soup {
 public:
  void add(const Vec3& a, const Vec3& b, const Vec3& c) {
    const auto n = static_cast<std::uint32_t>(mesh_.vertices.size());
    mesh_.vertices.insert(mesh_.vertices.end(), {a, b, c});
    mesh_.faces.push_back({n, n + 1, n + 2});
  }
  // A quad a b c d (counter-clockwise) as two triangles.
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    add(a, b, c);
    add(a, c, d);
  }
  Mesh take() { return std::move(mesh_); }

 private:
  Mesh mesh_;
};

constexpr double kPi = 3.141592653589793;

Mesh sphere(int n, double r) {
  Soup s;
  const auto at = [&](int ring, int seg) {
    const double theta = kPi * ring / n, phi = 2 * kPi * seg / (2 * n);
    return Vec3{r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta)};
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < 2 * n; ++j) {
      const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (i > 0) s.add(a, b, d);
      if (i < n - 1) s.add(b, c, d);
    }
  }
  return s.take();
}

Mesh torus(int n, double size) {
  Soup s;
  const double big = 0.7 * size, small = 0.3 * size;
  const auto at = [&](int i, int j) {
    const double u = 2 * kPi * i / (2 * n), v = 2 * kPi * j / n;
    return Vec3{(big + small * std::cos(v)) * std::cos(u), (big + small * std::cos(v)) * std::sin(u), small * std::sin(v)};
  };
  for (int i = 0; i < 2 * n; ++i) {
    for (int j = 0; j < n; ++j) s.quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  }
  return s.take();
}

Mesh terrain(int n, double size, Random& random) {
  std::vector<double> height((n + 1) * (n + 1));
  for (double& h : height) h = random.between(-0.2, 0.2) * size;
  const auto at = [&](int i, int j) {
    return Vec3{size * (2.0 * i / n - 1), size * (2.0 * j / n - 1), height[i * (n + 1) + j]};
  };
  Soup s;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) s.quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  }
  return s.take();
}

Mesh plate(int n, double size, double thickness) {
  Soup s;
  const double h = 0.5 * thickness;
  const auto at = [&](int i, int j, double z) { return Vec3{size * (2.0 * i / n - 1), size * (2.0 * j / n - 1), z}; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      s.quad(at(i, j, h), at(i + 1, j, h), at(i + 1, j + 1, h), at(i, j + 1, h));
      s.quad(at(i, j, -h), at(i, j + 1, -h), at(i + 1, j + 1, -h), at(i + 1, j, -h));
    }
  }
  if (thickness > 0) {  // the rim
    const Vec3 c[4] = {{-size, -size, 0}, {size, -size, 0}, {size, size, 0}, {-size, size, 0}};
    for (int k = 0; k < 4; ++k) {
      const Vec3 p = c[k], q = c[(k + 1) % 4];
      s.quad(p + Vec3{0, 0, -h}, q + Vec3{0, 0, -h}, q + Vec3{0, 0, h}, p + Vec3{0, 0, h});
    }
  }
  return s.take();
}

Mesh soup(int count, double size, Random& random) {
  Soup s;
  for (int i = 0; i < count; ++i) {
    const Vec3 centre{random.between(-size, size), random.between(-size, size), random.between(-size, size)};
    const double reach = size * std::ldexp(1.0, -static_cast<int>(random.below(12)));  // 1 .. 2^-11
    std::array<Vec3, 3> v;
    for (Vec3& p : v) p = centre + Vec3{random.between(-reach, reach), random.between(-reach, reach), random.between(-reach, reach)};
    s.add(v[0], v[1], v[2]);
  }
  return s.take();
}

// Replaces some faces by a segment (a repeated vertex, or a midpoint) or a point of the face.
void degenerate(Mesh& mesh, int percent, Random& random) {
  for (auto& f : mesh.faces) {
    if (static_cast<int>(random.below(100)) >= percent) continue;
    Vec3& a = mesh.vertices[f[0]];
    Vec3& b = mesh.vertices[f[1]];
    Vec3& c = mesh.vertices[f[2]];
    switch (random.below(3)) {
      case 0: c = b; break;                      // two equal vertices
      case 1: c = 0.5 * (a + b); break;          // collinear (up to rounding of the midpoint)
      default: b = a, c = a; break;              // a point
    }
  }
}

}  // namespace

Mesh make_mesh(const ProceduralMesh& recipe) {
  Random random(recipe.seed);
  const int n = std::clamp(recipe.resolution, 1, 200);
  Mesh mesh;
  switch (recipe.shape) {
    case ProceduralMesh::Shape::sphere: mesh = sphere(std::max(n, 2), recipe.size); break;
    case ProceduralMesh::Shape::torus: mesh = torus(std::max(n, 3), recipe.size); break;
    case ProceduralMesh::Shape::terrain: mesh = terrain(n, recipe.size, random); break;
    case ProceduralMesh::Shape::plate: mesh = plate(n, recipe.size, recipe.thickness); break;
    case ProceduralMesh::Shape::soup: mesh = soup(n, recipe.size, random); break;
  }
  degenerate(mesh, recipe.degenerate_percent, random);
  return mesh;
}

}  // namespace cc
