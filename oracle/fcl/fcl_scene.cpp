#include "oracle/fcl/fcl_scene.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/fcl_managers.h"

namespace cc::fcl_oracle {
namespace {

using Model = fcl::BVHModel<fcl::OBBRSSd>;

fcl::Transform3d transform_of(const RigidTransform& t) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = to_fcl(t.rotation);
  tf.translation() = to_fcl(t.translation);
  return tf;
}

}  // namespace

struct FclScene::Impl {
  std::unique_ptr<fcl::BroadPhaseCollisionManagerd> manager;
  std::map<const Mesh*, std::shared_ptr<Model>> models;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  std::map<const fcl::CollisionObjectd*, std::size_t> number;
  bool registered = false;
};

std::vector<std::string> FclScene::managers() { return fcl_manager_names(); }

FclScene::FclScene(const std::string& manager, const Aabb& world) : impl_(std::make_unique<Impl>()) {
  impl_->manager = make_fcl_manager(manager, world, 4);  // cells of about two rock diameters
}

FclScene::~FclScene() = default;

void FclScene::add(const std::shared_ptr<const Mesh>& mesh, const RigidTransform& pose) {
  auto& model = impl_->models[mesh.get()];
  if (!model) {
    model = std::make_shared<Model>();
    std::vector<fcl::Vector3d> vertices;
    for (const Vec3& v : mesh->vertices) vertices.push_back(to_fcl(v));
    std::vector<fcl::Triangle> triangles;
    for (const auto& f : mesh->faces) triangles.emplace_back(f[0], f[1], f[2]);
    model->beginModel();
    model->addSubModel(vertices, triangles);
    model->endModel();
  }
  auto object = std::make_unique<fcl::CollisionObjectd>(model, transform_of(pose));
  object->computeAABB();
  impl_->number[object.get()] = impl_->objects.size();
  impl_->objects.push_back(std::move(object));
}

void FclScene::move(std::size_t i, const RigidTransform& pose) {
  impl_->objects.at(i)->setTransform(transform_of(pose));
  impl_->objects[i]->computeAABB();
}

std::vector<Aabb> FclScene::boxes() const {
  std::vector<Aabb> out;
  for (const auto& o : impl_->objects) {
    const fcl::AABBd& b = o->getAABB();
    out.push_back({{b.min_[0], b.min_[1], b.min_[2]}, {b.max_[0], b.max_[1], b.max_[2]}});
  }
  return out;
}

std::vector<ObjectContact> FclScene::collide(std::size_t& candidates) {
  if (!impl_->registered) {
    std::vector<fcl::CollisionObjectd*> all;
    for (auto& o : impl_->objects) all.push_back(o.get());
    impl_->manager->registerObjects(all);
    impl_->manager->setup();
    impl_->registered = true;
  } else {
    impl_->manager->update();
  }
  struct Data {
    Impl* impl;
    std::vector<ObjectContact> contacts;
    std::size_t candidates = 0;
  } data{impl_.get(), {}, 0};
  const auto callback = [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* user) {
    auto* d = static_cast<Data*>(user);
    ++d->candidates;
    std::size_t a = d->impl->number.at(o1), b = d->impl->number.at(o2);
    if (a > b) std::swap(a, b), std::swap(o1, o2);
    fcl::CollisionRequestd request(std::numeric_limits<std::size_t>::max(), false);
    fcl::CollisionResultd result;
    fcl::collide(o1, o2, request, result);
    std::vector<fcl::Contactd> contacts;
    result.getContacts(contacts);
    if (contacts.empty()) return false;
    ObjectContact c{{static_cast<ObjectId>(a), static_cast<ObjectId>(b)}, {}};
    for (const fcl::Contactd& k : contacts) {  // b1 is o1's triangle: o1 was passed first
      c.triangles.emplace_back(static_cast<std::uint32_t>(k.b1), static_cast<std::uint32_t>(k.b2));
    }
    std::sort(c.triangles.begin(), c.triangles.end());
    c.triangles.erase(std::unique(c.triangles.begin(), c.triangles.end()), c.triangles.end());
    d->contacts.push_back(std::move(c));
    return false;
  };
  impl_->manager->collide(&data, callback);
  std::sort(data.contacts.begin(), data.contacts.end(), [](const ObjectContact& x, const ObjectContact& y) { return x.objects < y.objects; });
  candidates = data.candidates;
  return data.contacts;
}

}  // namespace cc::fcl_oracle
