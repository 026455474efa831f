// Rays as probes: a car driving over a terrain, one ray down from each of its four wheels. A
// wheel's signed distance is 0 on the road, positive above it and negative into it; the simple
// response moves the car down or up by their mean, so that it follows the road.
#pragma once

#include <array>
#include <memory>

#include "collide/bvh.h"
#include "collide/ray_mesh.h"

namespace cc::harness {

struct WheelProbe {
  Ray ray;
  RayMeshHit hit;     // the ray's closest hit on the road
  double distance;    // signed: the wheel's height above the road (NaN where no road is below)
};

class CarOnRoad {
 public:
  /// A car on a terrain of the given seed (a height field 100 long, 40 wide), at its start.
  explicit CarOnRoad(std::uint64_t seed);

  /// Probes the road under the four wheels, then drives on one step and applies the response.
  std::array<WheelProbe, 4> step();

  double height() const { return height_; }
  const Mesh& road() const { return *road_; }
  const Bvh<Obb>& road_hierarchy() const { return *bvh_; }

 private:
  std::shared_ptr<const Mesh> road_;
  std::shared_ptr<const Bvh<Obb>> bvh_;
  double x_ = -40, y_ = 0, height_ = 3;  // the car's centre; wheels at +-1.5 along, +-0.8 across
};

}  // namespace cc::harness
