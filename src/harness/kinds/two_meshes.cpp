// The pieces of the kinds on two placed meshes: FCL's test meshes (env.obj against rob.obj) at
// random poses drawn the way FCL's own test draws them, poses bisected to near contact, exact
// vertex-to-vertex contact under exact poses, and procedural meshes of every shape, with
// degenerate triangles mixed in; the library's hierarchy (volume type, build, split rule,
// update, descent) drawn per case too. The library's call, and what the cases are.
#include "harness/kinds/two_meshes.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "harness/formats/mesh_files.h"
#include "harness/generation/meshes.h"
#include "harness/generation/mesh_poses.h"
#include "harness/generation/regimes.h"
#include "harness/generation/rotation.h"
#include "harness/generation/touch.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"
#include "harness/model/mesh_collide.h"

namespace cc::harness {
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

// The farthest vertex from the mesh's origin.
Vec3 farthest_vertex(const Mesh& mesh) {
  Vec3 far;
  for (const Vec3& p : mesh.vertices) {
    if (dot(p, p) > dot(far, far)) far = p;
  }
  return far;
}

// A proper rotation stretched, within the orthonormality tolerance, as far as it can stretch the
// mesh's farthest vertex, and turning that vertex onto a coordinate axis: the rotation that takes
// a vertex furthest beyond its distance from the origin (bounding_cube's orthonormality term).
// R = Q S: S = I + e/2 s s^T for the vertex's sign pattern s (Gram matrix I + e s s^T + O(e^2),
// e just below the tolerance), which stretches a vertex v by about e |v|_1^2 / (2 |v|^2); Q the
// proper rotation (two reflections) that takes S v onto axis k.
Mat3 stretched_toward(ValueSource& v, const Vec3& vertex) {
  Choices& c = v.choices();
  Vec3 s;
  for (int i = 0; i < 3; ++i) s[i] = vertex[i] < 0 ? -1.0 : 1.0;
  const int k = static_cast<int>(c.draw(3)), other = (k + 1 + static_cast<int>(c.draw(2))) % 3;
  // The largest stretch whose rotation passes (Q's own rounding, a few u, uses up a little of the
  // tolerance of 32u: the first shares fail now and then). The last leaves 9.6u; the fallback
  // after it is defensive.
  for (const double share : {0.95, 0.9, 0.85, 0.8, 0.75, 0.7}) {  // GCOVR_EXCL_BR_LINE: the loop's end
    const double e = share * kObbOrthonormalTolerance;
    Mat3 stretch;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) stretch(i, j) += 0.5 * e * s[i] * s[j];
    }
    const Vec3 sv = stretch * vertex;
    Vec3 axis;
    axis[k] = std::sqrt(dot(sv, sv));
    const Vec3 w = sv - axis;  // the reflection across w's normal plane takes sv to the axis
    Mat3 q;
    if (max_abs(w) > 0) {  // GCOVR_EXCL_BR_LINE: w is 0 only for a mesh all at its origin
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) q(i, j) -= 2 * w[i] * w[j] / dot(w, w);
      }
      for (int j = 0; j < 3; ++j) q(other, j) = -q(other, j);  // a second reflection: proper
    }
    const Mat3 r = multiply(q, stretch);
    if (within_tolerance(r)) return r;
  }
  return draw_rotation(v);
}

// Poses in the regimes of the object bounds' and the transforms' bounds: rotations at the
// orthonormality tolerance (general, or stretched toward the farthest vertex), translations up
// to 2^40 times the meshes' size.
void poses_at_the_bound(MeshPair& m, ValueSource& v) {
  Choices& c = v.choices();
  const double size = std::sqrt(std::max(dot(farthest_vertex(*m.a.mesh), farthest_vertex(*m.a.mesh)), 0x1p-40));
  for (auto [pose, mesh] : {std::pair{&m.pose_a, m.a.mesh.get()}, std::pair{&m.pose_b, m.b.mesh.get()}}) {
    switch (c.draw(3)) {
      case 0: pose->rotation = stretched_toward(v, farthest_vertex(*mesh)); break;
      case 1: pose->rotation = perturb_to_tolerance(v, draw_rotation(v)); break;
      default: pose->rotation = draw_rotation(v);
    }
  }
  // Far from the origin by a power of two times small integers: placing a vertex there rounds as
  // a generic translation would, and the exact reference's rationals stay short.
  const int far = static_cast<int>(c.draw(41));
  for (int k = 0; k < 3; ++k) m.pose_a.translation[k] = std::ldexp(size, far) * v.small_int(3);
  m.pose_b.translation = m.pose_a.translation;
}

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
  switch (c.draw(fcl_meshes ? 3 : 4)) {
    case 3:  // rotations at the tolerance, far from the origin, then brought to near contact
      poses_at_the_bound(m, v);
      bisect_to_contact(m, c);
      break;
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

constexpr std::string_view kConfigurations[] = {"touching", "exact poses", "rotation at the tolerance",
                                                "far from the origin", "degenerate face"};

}  // namespace

template <CollisionMode Mode>
Answer TwoMeshes<Mode>::ask(const In& in) {
  Answer a;
  a.pairs = library_collide(in.meshes, Mode).pairs;
  a.hit = !a.pairs.empty();
  return a;
}

template <CollisionMode Mode>
TwoMeshesInput<Mode> TwoMeshes<Mode>::generate(ValueSource& v, const GenerateOptions& options) {
  return {generate_meshes(v, options)};
}

template <CollisionMode Mode>
void TwoMeshes<Mode>::touch(In& in, ValueSource& v) {
  touch_at_vertices(in.meshes, v.choices());
}

template <CollisionMode Mode>
Features TwoMeshes<Mode>::features(const In& in) {
  const MeshPair& m = in.meshes;
  Features f;
  Mat3 relative_rotation;
  for (int c = 0; c < 3; ++c) relative_rotation.col[c] = transpose_times(m.pose_a.rotation, m.pose_b.rotation.col[c]);
  f.parallel = true;
  for (const Vec3& col : relative_rotation.col) {
    int units = 0, zeros = 0;
    for (int k = 0; k < 3; ++k) units += std::fabs(col[k]) == 1, zeros += col[k] == 0;
    f.parallel &= units == 1 && zeros == 2;
  }
  for (const MeshRef* r : {&m.a, &m.b}) {
    for (std::size_t i = 0; i < r->mesh->size() && !f.degenerate; ++i) f.degenerate = degenerate(r->mesh->triangle(i));
  }
  return f;
}

template <CollisionMode Mode>
std::span<const std::string_view> TwoMeshes<Mode>::configurations() {
  return kConfigurations;
}

template <CollisionMode Mode>
void TwoMeshes<Mode>::recognise(const In& in, Configurations& found) {
  const MeshPair& m = in.meshes;
  found.margins();
  const auto exact_pose = [](const RigidTransform& t) { return off_orthonormal(t.rotation) == 0; };
  found.add("exact poses", exact_pose(m.pose_a) && exact_pose(m.pose_b));
  found.add("rotation at the tolerance",
            std::max(off_orthonormal(m.pose_a.rotation), off_orthonormal(m.pose_b.rotation)) >= kAtTheTolerance);
  double size = 0;
  bool degenerate_face = false;
  for (const MeshRef* r : {&m.a, &m.b}) {
    for (const Vec3& p : r->mesh->vertices) size = std::max(size, max_abs(p));
    for (std::size_t i = 0; i < r->mesh->size() && !degenerate_face; ++i) degenerate_face = normal(r->mesh->triangle(i)) == Vec3{};
  }
  found.add("degenerate face", degenerate_face);
  found.far(std::max(max_abs(m.pose_a.translation), max_abs(m.pose_b.translation)), size);
}

template struct TwoMeshes<CollisionMode::all_pairs>;
template struct TwoMeshes<CollisionMode::first_hit>;

}  // namespace cc::harness
