// Uses the installed library as another project would: a few primitive tests and two
// hierarchies. Exits 0 when every answer is the known one.
#include <collide/bvh.h>
#include <collide/bvh_collide.h>
#include <collide/obb.h>
#include <collide/procedural_mesh.h>
#include <collide/ray_aabb.h>
#include <collide/sphere.h>

#include <cstdio>

int main() {
  using namespace cc;
  int failures = 0;
  const auto expect = [&](bool ok, const char* what) {
    if (!ok) ++failures, std::printf("wrong: %s\n", what);
  };
  expect(test_sphere_sphere({{0, 0, 0}, 1}, {{2, 0, 0}, 1}), "spheres touching at one point overlap");
  expect(!test_sphere_sphere({{0, 0, 0}, 1}, {{3, 0, 0}, 1}), "spheres apart do not");
  expect(intersect_ray_aabb({{-2, 0.5, 0.5}, {1, 0, 0}, 0, 10}, {{0, 0, 0}, {1, 1, 1}}).hit, "a ray through a box hits it");
  const Obb a{{0, 0, 0}, {1, 1, 1}, Mat3::identity()}, b{{2, 0, 0}, {1, 1, 1}, Mat3::identity()};
  expect(test_obb_obb(a, b), "boxes sharing a face overlap");

  const Mesh torus = make_mesh({ProceduralMesh::Shape::torus, 0, 8, 1.0});
  const Bvh<Obb> tree = build_bvh<Obb>(torus, {});
  const RigidTransform here{Mat3::identity(), {0, 0, 0}}, beside{Mat3::identity(), {0.5, 0, 0}}, far{Mat3::identity(), {5, 0, 0}};
  expect(!collide(tree, here, tree, beside, {}).pairs.empty(), "two tori half a radius apart collide");
  expect(collide(tree, here, tree, far, {}).pairs.empty(), "two tori far apart do not");
  std::printf("%s\n", failures == 0 ? "consumer: every answer right" : "consumer: wrong answers");
  return failures == 0 ? 0 : 1;
}
