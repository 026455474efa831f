// FCL's mesh-mesh collision, for the mesh kinds' units: BVHModel<OBBd>, <OBBRSSd>, <AABBd>,
// <KDOPd<18>>, <kIOSd> and <RSSd>, asked for all contacts or for the first; FCL's contact
// points, for comparing collision determination; and its mesh distance.
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/bv/RSS.h>
#include <fcl/math/bv/kDOP.h>
#include <fcl/math/bv/kIOS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

#include "oracle/fcl/convert.h"
#include "oracle/fcl/parties.h"

namespace cc::fcl_oracle {
namespace {

template <class BV>
using Model = fcl::BVHModel<BV>;

// A model per mesh and volume type, built once and kept while the mesh lives.
template <class BV>
std::shared_ptr<const Model<BV>> model_of(const std::shared_ptr<const Mesh>& mesh) {
  struct Entry {
    std::weak_ptr<const Mesh> mesh;
    std::shared_ptr<const Model<BV>> model;
  };
  static std::map<const Mesh*, Entry> cache;
  if (auto it = cache.find(mesh.get()); it != cache.end()) {
    if (it->second.mesh.lock() == mesh) return it->second.model;
    cache.erase(it);
  }
  if (cache.size() > 64) std::erase_if(cache, [](const auto& e) { return e.second.mesh.expired(); });
  std::vector<fcl::Vector3d> vertices;
  for (const Vec3& v : mesh->vertices) vertices.push_back(to_fcl(v));
  std::vector<fcl::Triangle> triangles;
  for (const auto& f : mesh->faces) triangles.emplace_back(f[0], f[1], f[2]);
  auto model = std::make_shared<Model<BV>>();
  model->beginModel();
  model->addSubModel(vertices, triangles);
  model->endModel();
  cache[mesh.get()] = {mesh, model};
  return model;
}

fcl::Transform3d to_fcl(const RigidTransform& t) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = cc::fcl_oracle::to_fcl(t.rotation);
  tf.translation() = cc::fcl_oracle::to_fcl(t.translation);
  return tf;
}

template <class BV>
Opinion collide_models(const harness::MeshPair& m, bool first_only) {
  if (m.a.mesh->size() == 0 || m.b.mesh->size() == 0) return not_applicable("a mesh without triangles");
  const auto a = model_of<BV>(m.a.mesh), b = model_of<BV>(m.b.mesh);
  fcl::CollisionRequestd request(first_only ? 1 : std::numeric_limits<std::size_t>::max(), false);
  fcl::CollisionResultd result;
  fcl::collide(a.get(), to_fcl(m.pose_a), b.get(), to_fcl(m.pose_b), request, result);
  std::vector<fcl::Contactd> contacts;
  result.getContacts(contacts);
  Opinion o = answered(!contacts.empty());
  for (const fcl::Contactd& c : contacts) {
    o.answer.pairs.emplace_back(static_cast<std::uint32_t>(c.b1), static_cast<std::uint32_t>(c.b2));
  }
  std::sort(o.answer.pairs.begin(), o.answer.pairs.end());
  o.answer.pairs.erase(std::unique(o.answer.pairs.begin(), o.answer.pairs.end()), o.answer.pairs.end());
  return o;
}

template <class BV>
FclMeshDistance distance_models(const harness::MeshPair& m) {
  const auto a = model_of<BV>(m.a.mesh), b = model_of<BV>(m.b.mesh);
  fcl::DistanceRequestd request(true);  // with nearest points
  fcl::DistanceResultd result;
  fcl::distance(a.get(), to_fcl(m.pose_a), b.get(), to_fcl(m.pose_b), request, result);
  const auto& p = result.nearest_points;
  return {result.min_distance,
          {p[0].x(), p[0].y(), p[0].z()},
          {p[1].x(), p[1].y(), p[1].z()},
          static_cast<std::uint32_t>(result.b1),
          static_cast<std::uint32_t>(result.b2)};
}

}  // namespace

FclMeshDistance fcl_mesh_distance(Volume volume, const harness::MeshPair& m) {
  switch (volume) {
    case Volume::rss: return distance_models<fcl::RSSd>(m);
    case Volume::obbrss: return distance_models<fcl::OBBRSSd>(m);
    default: throw std::invalid_argument("FCL's mesh distance takes RSS or OBBRSS models");
  }
}

std::vector<FclContact> fcl_mesh_contacts(const harness::MeshPair& m) {
  if (m.a.mesh->size() == 0 || m.b.mesh->size() == 0) return {};
  const auto a = model_of<fcl::OBBRSSd>(m.a.mesh), b = model_of<fcl::OBBRSSd>(m.b.mesh);
  fcl::CollisionRequestd request(std::numeric_limits<std::size_t>::max(), true);
  fcl::CollisionResultd result;
  fcl::collide(a.get(), to_fcl(m.pose_a), b.get(), to_fcl(m.pose_b), request, result);
  std::vector<fcl::Contactd> contacts;
  result.getContacts(contacts);
  std::vector<FclContact> out;
  for (const fcl::Contactd& c : contacts) {
    out.push_back({static_cast<std::uint32_t>(c.b1), static_cast<std::uint32_t>(c.b2), {c.pos.x(), c.pos.y(), c.pos.z()},
                   {c.normal.x(), c.normal.y(), c.normal.z()}, c.penetration_depth});
  }
  return out;
}

Opinion fcl_collide_models(Volume volume, const harness::MeshPair& m, bool first_only) {
  switch (volume) {
    case Volume::obb: return collide_models<fcl::OBBd>(m, first_only);
    case Volume::obbrss: return collide_models<fcl::OBBRSSd>(m, first_only);
    case Volume::aabb: return collide_models<fcl::AABBd>(m, first_only);
    case Volume::kdop18: return collide_models<fcl::KDOPd<18>>(m, first_only);
    case Volume::kios: return collide_models<fcl::kIOSd>(m, first_only);
    case Volume::rss: return collide_models<fcl::RSSd>(m, first_only);
  }
  return failed("an unknown volume type");
}

}  // namespace cc::fcl_oracle
