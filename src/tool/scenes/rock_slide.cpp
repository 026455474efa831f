#include "tool/scenes/rock_slide.h"

#include <cmath>
#include <random>

#include "collide/procedural_mesh.h"

namespace cc::harness {
namespace {

constexpr double kFrame = 1.0 / 60;

// The rotation by `angle` about the unit vector `axis` (Rodrigues).
Mat3 rotation_about(const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  return Mat3::from_columns({t * x * x + c, t * x * y + s * z, t * x * z - s * y},
                            {t * x * y - s * z, t * y * y + c, t * y * z + s * x},
                            {t * x * z + s * y, t * y * z - s * x, t * z * z + c});
}

}  // namespace

RockSlide::RockSlide(const RockSlideOptions& options) {
  using Shape = ProceduralMesh::Shape;
  for (const ProceduralMesh& recipe : {ProceduralMesh{Shape::sphere, 1, 6, 1.0}, ProceduralMesh{Shape::sphere, 2, 4, 0.6},
                                       ProceduralMesh{Shape::torus, 3, 5, 0.8}, ProceduralMesh{Shape::soup, 4, 40, 0.7},
                                       ProceduralMesh{Shape::plate, 5, 2, 0.9, 0.3}}) {
    shapes_.push_back(std::make_shared<const Mesh>(make_mesh(recipe)));
  }
  // About one rock per 12 square units of slope: crowded enough that some touch every frame.
  const double area = 12.0 * options.rocks;
  length_ = std::sqrt(2 * area), width_ = area / length_;
  slope_ = options.slope_degrees * 3.141592653589793 / 180;
  std::mt19937_64 random(options.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < options.rocks; ++i) {
    Rock r;
    r.mesh = shapes_[static_cast<std::size_t>(i) % shapes_.size()];
    r.along = length_ * unit(random), r.across = width_ * unit(random), r.height = 1 + 2 * unit(random);
    r.speed = 2 + 4 * unit(random);
    const Vec3 axis{unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5};
    r.axis = (1 / std::sqrt(dot(axis, axis))) * axis;
    r.angle = 6.283185307179586 * unit(random), r.spin = 4 * (unit(random) - 0.5);
    rocks_.push_back(r);
  }
}

RigidTransform RockSlide::pose_of(std::size_t i) const {
  const Rock& r = rocks_[i];
  // The slope descends along x: its surface is z = -x tan(slope); heights are above it.
  RigidTransform t;
  t.rotation = rotation_about(r.axis, r.angle);
  t.translation = {r.along * std::cos(slope_), r.across, -r.along * std::sin(slope_) + r.height};
  return t;
}

void RockSlide::step() {
  for (Rock& r : rocks_) {
    r.along += r.speed * kFrame;
    if (r.along > length_) r.along -= length_;  // back to the top
    r.angle += r.spin * kFrame;
  }
}

}  // namespace cc::harness
