#include "collide/collision_world.h"

namespace cc {

template <class BV>
ObjectId CollisionWorld<BV>::add(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const Bvh<BV>> bvh,
                                 const RigidTransform& pose) {
  Object o{std::move(mesh), std::move(bvh), pose, 0, {}, true};
  o.radius = rotation_radius(*o.mesh);
  o.ball = mesh_ball(*o.mesh);
  objects_.push_back(std::move(o));
  const ObjectId id = sap_.add(box_of(static_cast<ObjectId>(objects_.size() - 1)));
  return id;  // sap_ and objects_ count alike: both never reuse ids
}

template <class BV>
void CollisionWorld<BV>::remove(ObjectId id) {
  sap_.remove(id);
  objects_.at(id).alive = false;
  objects_[id].mesh.reset();
  objects_[id].bvh.reset();
}

template <class BV>
Aabb CollisionWorld<BV>::box_of(ObjectId id) const {
  const Object& o = objects_.at(id);
  switch (bounds_) {
    case RotationBounds::refit: return fitted_box(*o.mesh, o.pose);
    case RotationBounds::bounding_sphere: return cc::box_of(placed_ball(o.ball, o.pose));
    case RotationBounds::bounding_cube: break;
  }
  return bounding_cube(o.radius, o.pose);
}

template <class BV>
const std::vector<ObjectPair>& CollisionWorld<BV>::broad_phase() {
  for (ObjectId id = 0; id < objects_.size(); ++id) {
    if (objects_[id].alive) sap_.move(id, box_of(id));
  }
  sap_.update();
  candidates_ = sap_.pairs();
  if (bounds_ == RotationBounds::bounding_sphere) {
    std::erase_if(candidates_, [this](const ObjectPair& p) {
      const Object &a = objects_[p.first], &b = objects_[p.second];
      return !test_sphere_sphere(placed_ball(a.ball, a.pose), placed_ball(b.ball, b.pose));
    });
  }
  return candidates_;
}

template <class BV>
std::vector<ObjectContact> CollisionWorld<BV>::narrow_phase() const {
  std::vector<ObjectContact> out;
  for (const ObjectPair& p : candidates_) {
    const Object &a = objects_[p.first], &b = objects_[p.second];
    CollisionResult r = collide(*a.bvh, a.pose, *b.bvh, b.pose, options_);
    if (!r.pairs.empty()) out.push_back({p, std::move(r.pairs)});
  }
  return out;
}

#define CC_INSTANTIATE(BV) template class CollisionWorld<BV>;
CC_FOR_EACH_BOUNDING_VOLUME(CC_INSTANTIATE)
#undef CC_INSTANTIATE

}  // namespace cc
