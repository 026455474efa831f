// The fields of the parts query inputs are made of (see fields.h): boxes, spheres, rays, moving
// boxes, poses, pairs of placed meshes, discs and walls. Their order is the order of the case
// file's members and of the fuzz record's values. A std::vector of a part made of fields is a
// list of parts (a maze's walls): each format handles it element by element.
#pragma once

#include <optional>
#include <type_traits>
#include <vector>

#include "collide/aabb.h"
#include "collide/disc_walls.h"
#include "collide/moving_box.h"
#include "collide/obb.h"
#include "collide/ray.h"
#include "collide/rigid_transform.h"
#include "collide/sphere.h"
#include "harness/model/fields.h"
#include "harness/model/mesh_query.h"

namespace cc::harness {

/// A set of boxes over a sequence of frames: frames[f][i] is box i in frame f, or nothing when
/// box i is not in the scene then. Every frame has the same number of slots. (A leaf: in a case
/// file an array per frame of {"lo", "hi"} or null.)
using BoxFrames = std::vector<std::vector<std::optional<Aabb>>>;

template <>
struct Fields<Aabb> {
  static constexpr auto list = std::tuple{field<&Aabb::lo>("lo"), field<&Aabb::hi>("hi")};
};

template <>
struct Fields<Obb> {
  static constexpr auto list =
      std::tuple{field<&Obb::center>("center"), field<&Obb::half>("half"), field<&Obb::axes, AsFrame>("axes")};
};

template <>
struct Fields<Sphere> {
  static constexpr auto list = std::tuple{field<&Sphere::center>("center"), field<&Sphere::radius>("radius")};
};

/// A disc in the plane: its centre (a 2-D point, a leaf: ["x", "y"]) and radius.
template <>
struct Fields<Disc> {
  static constexpr auto list = std::tuple{field<&Disc::center>("center"), field<&Disc::radius>("radius")};
};

/// A wall: the segment between its ends.
template <>
struct Fields<Wall> {
  static constexpr auto list = std::tuple{field<&Wall::a>("a"), field<&Wall::b>("b")};
};

/// A list of parts made of fields, such as walls.
template <class T>
concept PartList = requires { typename T::value_type; } && std::is_same_v<T, std::vector<typename T::value_type>> &&
                   HasFields<typename T::value_type>;

template <>
struct Fields<Ray> {
  static constexpr auto list = std::tuple{field<&Ray::origin>("origin"), field<&Ray::dir>("dir"),
                                          field<&Ray::tmin>("tmin"), field<&Ray::tmax>("tmax")};
};

/// A moving box: the box's own fields, then its velocity.
template <>
struct Fields<MovingObb> {
  static constexpr auto list = std::tuple{field<&MovingObb::box>(""), field<&MovingObb::velocity>("velocity")};
};

template <>
struct Fields<RigidTransform> {
  static constexpr auto list =
      std::tuple{field<&RigidTransform::rotation, AsRotation>("rotation"), field<&RigidTransform::translation>("translation")};
};

template <>
struct Fields<MeshPair> {
  static constexpr auto list = std::tuple{field<&MeshPair::a>("a"), field<&MeshPair::pose_a>("pose_a"),
                                          field<&MeshPair::b>("b"), field<&MeshPair::pose_b>("pose_b"),
                                          field<&MeshPair::library>("library")};
};

}  // namespace cc::harness
