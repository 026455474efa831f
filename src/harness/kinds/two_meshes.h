// What the kinds on two placed meshes share (every colliding pair of triangles; the first one
// found): every piece of their units but the answer's judgement and what only one of them has.
// Their input, the same for both but for what is asked, is model/inputs/two_meshes.h.
#pragma once

#include "harness/kinds/query.h"
#include "harness/model/inputs/two_meshes.h"

namespace cc::harness {

/// The band of the library's pairs of two placed meshes, whichever is asked.
inline constexpr Band kTwoMeshesBand = {
    0x1p-40, BandSides::two_sided, 0,
    "b's triangles move into a's frame in floating point (2^-49 of the scale per coordinate), which can part touching "
    "triangles, then the triangle test's 2^-44; 2^-40 leaves room for the conditioning of the deciding axis"};

/// The pieces both kinds share.
template <CollisionMode Mode>
struct TwoMeshes : QueryDefaults {
  using In = TwoMeshesInput<Mode>;
  static constexpr Band band = kTwoMeshesBand;
  /// The world's axes permuted (both poses' rows); the faces, or each face's vertices,
  /// reordered. A flip would make a pose an improper rotation; swapping the meshes transposes the
  /// pairs but moves a into b's frame instead, with other roundings; scaling would copy the meshes.
  static constexpr Relations relations = {Relation::permute_axes, Relation::permute_vertices, Relation::permute_faces};
  static constexpr bool builds_hierarchies = true;

  /// The colliding pairs (face of a, face of b), sorted; a first hit names one.
  static Answer ask(const In& in);
  /// FCL's test meshes (env.obj against rob.obj) at poses drawn as FCL's own test draws them,
  /// poses bisected to near contact, exact vertex-to-vertex contact under exact poses,
  /// procedural meshes of every shape with degenerate triangles mixed in; the hierarchy drawn
  /// per case.
  static In generate(ValueSource& values, const GenerateOptions& options);
  /// b translated so that one of its vertices meets one of a's.
  static void touch(In& in, ValueSource& values);
  /// Parallel: the meshes' frames aligned up to a permutation and flips of the axes (the
  /// relative rotation a signed permutation), so that axis-aligned faces of one are parallel to
  /// those of the other. Degenerate: a face of either mesh is a segment or a point.
  static Features features(const In& in);
  static std::span<const std::string_view> configurations();
  static void recognise(const In& in, Configurations& found);
};

}  // namespace cc::harness
