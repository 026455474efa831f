// A scene for the two-level pipeline: rocks tumbling down a slope. Simple motion, no collision
// response: each rock slides down the slope with its own speed and spin, and a rock that
// leaves the bottom comes back at the top.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "collide/mesh.h"
#include "collide/rigid_transform.h"

namespace cc::harness {

struct RockSlideOptions {
  int rocks = 300;
  std::uint64_t seed = 1;
  double slope_degrees = 20;
};

class RockSlide {
 public:
  explicit RockSlide(const RockSlideOptions& options);

  /// The rocks' meshes (a few procedural shapes, shared) and their poses now.
  std::size_t size() const { return rocks_.size(); }
  const std::shared_ptr<const Mesh>& mesh_of(std::size_t rock) const { return rocks_[rock].mesh; }
  const std::vector<std::shared_ptr<const Mesh>>& shapes() const { return shapes_; }
  RigidTransform pose_of(std::size_t rock) const;

  /// Advances every rock by one frame.
  void step();

 private:
  struct Rock {
    std::shared_ptr<const Mesh> mesh;
    double along = 0, across = 0, height = 0;  // position in the slope's frame
    double speed = 0;
    Vec3 axis;
    double angle = 0, spin = 0;
  };
  double length_ = 0, width_ = 0, slope_ = 0;
  std::vector<std::shared_ptr<const Mesh>> shapes_;
  std::vector<Rock> rocks_;
};

}  // namespace cc::harness
