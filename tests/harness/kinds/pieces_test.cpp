// The table of each kind's pieces (kinds/pieces.cpp): every entry is its unit's, and every unit
// says what it is.
#include "harness/model/kind_pieces.h"

#include <gtest/gtest.h>

#include "harness/generation/choices.h"
#include "harness/generation/generate.h"
#include "harness/generation/values.h"
#include "harness/judging/configurations.h"
#include "harness/kinds/aabb_aabb.h"
#include "harness/kinds/broadphase.h"
#include "harness/kinds/disc_walls.h"
#include "harness/kinds/kdop_kdop.h"
#include "harness/kinds/mesh_mesh.h"
#include "harness/kinds/mesh_mesh_distance.h"
#include "harness/kinds/mesh_mesh_first.h"
#include "harness/kinds/moving_obb.h"
#include "harness/kinds/obb_obb.h"
#include "harness/kinds/obb_obb_distance.h"
#include "harness/kinds/ray_aabb.h"
#include "harness/kinds/ray_mesh.h"
#include "harness/kinds/sphere_obb_distance.h"
#include "harness/kinds/sphere_sphere.h"
#include "harness/kinds/sphere_sphere_distance.h"
#include "harness/kinds/tri_aabb.h"
#include "harness/kinds/tri_obb.h"
#include "harness/kinds/tri_obb_distance.h"
#include "harness/kinds/tri_tri.h"
#include "harness/kinds/tri_tri_distance.h"
#include "harness/kinds/tri_tri_intersection.h"
#include "test_paths.h"

namespace cc::harness {
namespace {

// The constants and the lists are the unit's own; each function, called through the table on a
// case the table generated, answers as the unit's does on that case.
TEST(KindPieces, AreEachUnitsOwn) {
  for (QueryKind kind : kAllQueryKinds) {
    const KindPieces& p = pieces_of(kind);
    with_kind(kind, [&]<class In>() {
      using Q = Query<In>;
      EXPECT_EQ(p.band.width, Q::band.width) << name(kind);
      EXPECT_EQ(p.band.sides, Q::band.sides) << name(kind);
      EXPECT_EQ(p.band.why, Q::band.why) << name(kind);
      EXPECT_EQ(p.judged, Q::judged) << name(kind);
      EXPECT_EQ(p.builds_hierarchies, Q::builds_hierarchies) << name(kind);
      EXPECT_EQ(p.parallel_applies, Q::parallel_applies) << name(kind);
      for (Relation r : kAllRelations) EXPECT_EQ(p.relations.has(r), Q::relations.has(r)) << name(kind);
      EXPECT_EQ(p.configurations().data(), Q::configurations().data()) << name(kind);
      EXPECT_EQ(p.bound_terms().data(), Q::bound_terms().data()) << name(kind);

      RandomChoices table_choices(7), unit_choices(7);
      ValueSource table_values(table_choices, {}), unit_values(unit_choices, {});
      GenerateOptions options;
      options.mesh_folder = test::fcl_mesh_folder();
      Input in = p.generate(table_values, options);
      ASSERT_EQ(kind_of(in), kind);
      const In direct = Q::generate(unit_values, options);
      EXPECT_TRUE(std::get<In>(in) == direct) << name(kind);
      EXPECT_EQ(p.ask(in), Q::ask(direct)) << name(kind);
      const Features f = p.features(in), g = Q::features(direct);
      EXPECT_EQ(f.parallel, g.parallel) << name(kind);
      EXPECT_EQ(f.degenerate, g.degenerate) << name(kind);
      p.touch(in, table_values);
      In moved = direct;
      Q::touch(moved, unit_values);
      EXPECT_TRUE(std::get<In>(in) == moved) << name(kind);
    });
  }
}

// A piece asked of an input of another kind is a programming error, reported as one.
TEST(KindPieces, RefuseAnotherKindsInput) {
  const Input sphere = SphereSphereInput{};
  EXPECT_THROW(pieces_of(QueryKind::obb_obb).ask(sphere), std::bad_variant_access);
}

TEST(KindPieces, EveryUnitSaysWhatItIs) {
  for (QueryKind kind : kAllQueryKinds) {
    with_kind(kind, [kind]<class In>() {
      EXPECT_FALSE(Query<In>::band.why.empty()) << name(kind);
      EXPECT_FALSE(Query<In>::configurations().empty()) << name(kind);
      if constexpr (requires { Query<In>::library_parties(); }) {
        for (const Party<In>& p : Query<In>::library_parties()) {
          EXPECT_TRUE(p.name.starts_with("library.")) << p.name;
          EXPECT_EQ(p.band.width, Query<In>::band.width) << p.name;
          EXPECT_EQ(p.band.sides, Query<In>::band.sides) << p.name;
        }
      }
    });
  }
}

}  // namespace
}  // namespace cc::harness
