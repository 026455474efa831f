#include "tool/scenes/car_on_road.h"

#include <cmath>

#include "collide/procedural_mesh.h"

namespace cc::harness {
namespace {

constexpr double kProbe = 5;    // each ray starts this far above its wheel
constexpr double kStep = 0.75;  // distance driven per step

}  // namespace

CarOnRoad::CarOnRoad(std::uint64_t seed) {
  Mesh terrain = make_mesh({ProceduralMesh::Shape::terrain, seed, 60, 50.0});
  for (Vec3& v : terrain.vertices) v.y *= 0.4, v.z *= 0.05;  // a road 100 long, 40 wide, bumps up to 0.5
  road_ = std::make_shared<const Mesh>(std::move(terrain));
  bvh_ = std::make_shared<const Bvh<Obb>>(build_bvh<Obb>(*road_, {}));
}

std::array<WheelProbe, 4> CarOnRoad::step() {
  std::array<WheelProbe, 4> wheels;
  const double along[2] = {-1.5, 1.5}, across[2] = {-0.8, 0.8};
  double sum = 0;
  int on_road = 0;
  for (int i = 0; i < 4; ++i) {
    WheelProbe& w = wheels[static_cast<std::size_t>(i)];
    w.ray = {{x_ + along[i / 2], y_ + across[i % 2], height_ + kProbe}, {0, 0, -1}, 0, INFINITY};
    w.hit = ray_mesh_closest(*bvh_, w.ray);
    w.distance = w.hit.hit ? w.hit.t - kProbe : NAN;
    if (w.hit.hit) sum += w.distance, ++on_road;
  }
  if (on_road > 0) height_ -= sum / on_road;  // the response: down when above, up when into it
  x_ += kStep;
  return wheels;
}

}  // namespace cc::harness
