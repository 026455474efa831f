// Generators for mesh_mesh and mesh_mesh_first: FCL's test meshes (env.obj against rob.obj) at
// random poses drawn the way FCL's own test draws them, poses bisected to near contact, exact
// vertex-to-vertex contact under exact poses, and procedural meshes of every shape, with
// degenerate triangles mixed in. The library's hierarchy (volume type, build, split rule,
// update, descent) is drawn per case too.
#include <cmath>
#include <tuple>

#include "harness/generate_detail.h"
#include "harness/mesh_files.h"
#include "harness/mesh_poses.h"
#include "harness/rotation.h"
#include "harness/touch.h"

namespace cc::harness::detail {

// Any hierarchy; for FCL's meshes (`few`), one of a few per volume type, so that the campaign's
// workers build each once and reuse it over thousands of poses.
LibraryBvh draw_library(Choices& c, bool few) {
  LibraryBvh l;
  l.bv = kAllBvTypes[c.draw(std::size(kAllBvTypes))];
  l.build.strategy = static_cast<BuildStrategy>(c.draw(3));
  if (few) {
    constexpr std::pair<SplitAxis, SplitPoint> kRules[] = {{SplitAxis::longest_side, SplitPoint::midpoint},
                                                           {SplitAxis::splatter, SplitPoint::mean},
                                                           {SplitAxis::min_sum, SplitPoint::median}};
    std::tie(l.build.axis, l.build.point) = kRules[c.draw(3)];
    l.build.leaf_size = l.bv == BvType::obb ? 1 : 4;
  } else {
    l.build.axis = static_cast<SplitAxis>(c.draw(4));
    l.build.point = static_cast<SplitPoint>(c.draw(3));
    l.build.leaf_size = 1 + static_cast<int>(c.draw(4));
  }
  l.update = c.chance(50) ? BvUpdate::exact : BvUpdate::approximate;
  l.descent = c.chance(50) ? Descent::larger : Descent::first_model;
  return l;
}

ProceduralMesh draw_recipe(Choices& c, double size) {
  ProceduralMesh r;
  r.shape = static_cast<ProceduralMesh::Shape>(c.draw(5));
  r.seed = c.draw(1000);
  r.resolution = 2 + static_cast<int>(c.draw(10));
  r.size = size;
  r.thickness = c.chance(50) ? 0.0 : size * std::ldexp(1.0, -static_cast<int>(c.draw(30)));
  r.degenerate_percent = c.chance(30) ? static_cast<int>(c.draw(40)) : 0;
  return r;
}

namespace {

void out_of_contract(MeshPair& m, ValueSource& v) {
  Choices& c = v.choices();
  switch (c.draw(3)) {
    case 0: {  // a NaN or infinite coordinate
      Mesh broken = *m.b.mesh;
      broken.vertices[c.draw(broken.vertices.size())][static_cast<int>(c.draw(3))] = c.chance(50) ? NAN : INFINITY;
      m.b = triangles_mesh(std::move(broken));
      break;
    }
    case 1: m.pose_b.rotation = draw_non_orthonormal(v); break;
    default: m.pose_b.rotation.col[2] = -m.pose_b.rotation.col[2];  // a mirror
  }
}

}  // namespace

MeshPair generate_meshes(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  MeshPair m;
  const auto env = find_mesh_file("env.obj", options.mesh_folder), rob = find_mesh_file("rob.obj", options.mesh_folder);
  const bool fcl_meshes = env && rob && !c.chance(40);
  if (fcl_meshes) {
    m.a.source = m.b.source = MeshRef::Source::file;
    m.a.file = "meshes/env.obj", m.b.file = "meshes/rob.obj";
    m.a.mesh = load_mesh_file(*env), m.b.mesh = load_mesh_file(*rob);
  } else {
    const double size = std::ldexp(1.0, v.small_int(6));
    m.a = procedural_mesh(draw_recipe(c, size));
    m.b = procedural_mesh(draw_recipe(c, std::ldexp(size, v.small_int(3))));
  }
  m.library = draw_library(c, fcl_meshes);
  switch (c.draw(3)) {
    case 0:  // at random, the way FCL's test places rob.obj in env.obj
      if (fcl_meshes) {
        m.pose_b = fcl_style_pose(c);
      } else {
        m.pose_a.rotation = draw_rotation(v);
        m.pose_b.rotation = draw_rotation(v);
        m.pose_b.translation = v.point();
      }
      break;
    case 1:  // exact poses (signed permutations, simple translations), meeting at a vertex
      m.pose_a.rotation = table_rotation(c.draw(24));
      m.pose_b.rotation = table_rotation(c.draw(24));
      m.pose_a.translation = v.point();
      touch_at_vertices(m, c);
      break;
    default:  // brought to near contact along a random direction
      m.pose_a.rotation = fcl_meshes ? Mat3::identity() : draw_rotation(v);
      m.pose_b.rotation = fcl_meshes ? fcl_style_rotation(c) : draw_rotation(v);
      bisect_to_contact(m, c);
  }
  if (options.out_of_contract && c.chance(10)) out_of_contract(m, v);
  return m;
}

}  // namespace cc::harness::detail
