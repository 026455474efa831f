#include "harness/judging/metamorphic.h"

#include <gtest/gtest.h>
#include "test_paths.h"

#include "harness/generation/choices.h"
#include "harness/generation/generate.h"
#include "harness/formats/input_json.h"

#include <algorithm>
#include <set>

namespace cc::harness {
namespace {

std::string text(const Input& in) { return input_to_json(in).dump(); }

TEST(Transform, FlippingOrSwappingTwiceIsTheIdentity) {
  for (QueryKind kind : kAllQueryKinds) {
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
      RandomChoices c(seed);
      const Input in = generate(kind, c, {.mesh_folder = test::fcl_mesh_folder()});
      for (int axis = 0; axis < 3; ++axis) {
        const auto once = transform(in, Relation::flip_axis, axis);
        if (!once) continue;
        EXPECT_EQ(text(*transform(*once, Relation::flip_axis, axis)), text(in)) << name(kind);
      }
      if (const auto swapped = transform(in, Relation::swap_shapes, 0)) {
        EXPECT_EQ(text(*transform(*swapped, Relation::swap_shapes, 0)), text(in));
      }
    }
  }
}

TEST(Transform, ScalingUpAndDownIsTheIdentityOrDoesNotApply) {
  for (QueryKind kind : kAllQueryKinds) {
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
      RandomChoices c(seed);
      const Input in = flush_extremes(generate(kind, c, {.mesh_folder = test::fcl_mesh_folder()}));
      const auto up = transform(in, Relation::scale, 5);
      if (!relation_applies(kind, Relation::scale)) {
        EXPECT_FALSE(up.has_value());
        continue;
      }
      ASSERT_TRUE(up.has_value()) << name(kind) << " " << text(in);
      EXPECT_EQ(text(*transform(*up, Relation::scale, -5)), text(in));
    }
  }
  // 2^-1074 cannot be halved exactly: the relation does not apply.
  EXPECT_FALSE(transform(SphereSphereInput{{{5e-324, 0, 0}, 1}, {{0, 0, 0}, 1}}, Relation::scale, -1).has_value());
}

TEST(Transform, PermutingAxesMovesCoordinates) {
  const Input in = AabbAabbInput{{{1, 2, 3}, {4, 5, 6}}, {{0, 0, 0}, {1, 1, 1}}};
  const auto p = transform(in, Relation::permute_axes, 3);  // {1, 2, 0}: x' = y, y' = z, z' = x
  ASSERT_TRUE(p);
  EXPECT_EQ(std::get<AabbAabbInput>(*p).a.lo, (Vec3{2, 3, 1}));
}

TEST(Transform, KdopDirectionSetsNotClosedAreSkipped) {
  const Input k16 = KdopKdopInput{16, {{0, 0, 0}}, {{1, 1, 1}}};
  const Input k24 = KdopKdopInput{24, {{0, 0, 0}}, {{1, 1, 1}}};
  EXPECT_FALSE(transform(k16, Relation::permute_axes, 1));
  EXPECT_FALSE(transform(k16, Relation::flip_axis, 0));
  EXPECT_TRUE(transform(k24, Relation::permute_axes, 1));
  EXPECT_FALSE(transform(k24, Relation::flip_axis, 0));
  EXPECT_TRUE(transform(KdopKdopInput{26, {{0, 0, 0}}, {{1, 1, 1}}}, Relation::flip_axis, 2));
}

TEST(Transform, RaysAndTrianglesAgainstBoxesHaveNothingToSwap) {
  EXPECT_FALSE(transform(RayAabbInput{}, Relation::swap_shapes, 0));
  EXPECT_FALSE(transform(TriObbInput{}, Relation::swap_shapes, 0));
  EXPECT_TRUE(transform(TriTriInput{}, Relation::swap_shapes, 0));
}

TEST(Transform, ReorderingATriangleTakesEachOfTheSixOrders) {
  const Triangle t{{Vec3{1, 0, 0}, Vec3{0, 2, 0}, Vec3{0, 0, 3}}};
  std::set<std::string> orders;
  for (int p = 0; p < 6; ++p) {
    const auto r = transform(TriAabbInput{t, {}}, Relation::permute_vertices, p);
    ASSERT_TRUE(r);
    const Triangle& u = std::get<TriAabbInput>(*r).tri;
    orders.insert(text(TriTriInput{u, {}}));
    EXPECT_TRUE(std::is_permutation(u.v.begin(), u.v.end(), t.v.begin()));
  }
  EXPECT_EQ(orders.size(), 6u);
}

// A reordering keeps what is reordered, as a multiset, and moves some of it; the answer's faces
// or slots follow: pair (i, j) of the original names the same two things as the mapped pair of
// the reordered query.
TEST(Transform, ReorderingsMoveThingsAndTheAnswerFollows) {
  Mesh a, b;
  for (std::uint32_t f = 0; f < 9; ++f) {
    for (Mesh* m : {&a, &b}) {
      const double x = f + (m == &b ? 0.5 : 0);
      m->vertices.insert(m->vertices.end(), {Vec3{x, 0, 0}, Vec3{x, 1, 0}, Vec3{x, 0, 1}});
      m->faces.push_back({3 * f, 3 * f + 1, 3 * f + 2});
    }
  }
  MeshPair m{triangles_mesh(a), triangles_mesh(b), {}, {}, {}};
  const Input in = MeshMeshInput{m};
  for (int parameter : {1, 77, 123456}) {
    const auto r = transform(in, Relation::permute_faces, parameter);
    ASSERT_TRUE(r);
    const MeshPair& moved = *meshes_of(*r);
    int displaced = 0;
    for (std::uint32_t f = 0; f < 9; ++f) {
      // Face f of a and face f of b, renamed by the mapping of the pair (f, f).
      Answer one;
      one.pairs = {{f, f}};
      const FacePair to = mapped_answer(one, in, Relation::permute_faces, parameter).pairs[0];
      EXPECT_EQ(moved.a.mesh->triangle(to.first), a.triangle(f));
      EXPECT_EQ(moved.b.mesh->triangle(to.second), b.triangle(f));
      displaced += to.first != f;
    }
    EXPECT_GT(displaced, 0);
  }
  BroadphaseInput scene;
  scene.frames = {{Aabb{{0, 0, 0}, {1, 1, 1}}, std::nullopt, Aabb{{2, 0, 0}, {3, 1, 1}}, Aabb{{4, 0, 0}, {5, 1, 1}}}};
  const auto r = transform(scene, Relation::permute_objects, 5);
  ASSERT_TRUE(r);
  const auto& frame = std::get<BroadphaseInput>(*r).frames[0];
  Answer pair;
  pair.frames = {{{0, 3}}};
  const FacePair to = mapped_answer(pair, scene, Relation::permute_objects, 5).frames[0][0];
  EXPECT_LT(to.first, to.second);
  EXPECT_TRUE((frame[to.first] == scene.frames[0][0] && frame[to.second] == scene.frames[0][3]) ||
              (frame[to.first] == scene.frames[0][3] && frame[to.second] == scene.frames[0][0]));
  const KdopKdopInput k{18, {{1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}, {{5, 0, 0}, {6, 0, 0}}};
  const auto shuffled = std::get<KdopKdopInput>(*transform(k, Relation::permute_points, 9));
  EXPECT_TRUE(std::is_permutation(shuffled.a.begin(), shuffled.a.end(), k.a.begin()));
  EXPECT_TRUE(std::is_permutation(shuffled.b.begin(), shuffled.b.end(), k.b.begin()));
  EXPECT_FALSE(transform(SphereSphereInput{}, Relation::permute_points, 1));
  EXPECT_FALSE(transform(RayAabbInput{}, Relation::permute_vertices, 1));
}

// In the plane of a disc and walls: a permutation of the axes that puts y before x swaps them,
// the others leave the plane as it is; flipping x or y negates it, flipping z changes nothing;
// scaling scales the radius too.
TEST(Transform, APlaneSwapsXAndYAndIgnoresZ) {
  const Input in = DiscWallsInput{{{1, 2}, 0.5}, {{{3, 4}, {5, 6}}}};
  const auto walls_of = [](const Input& i) { return std::get<DiscWallsInput>(i); };
  for (int p : {2, 3, 5}) {  // {1, 0, 2}, {1, 2, 0}, {2, 1, 0}: y before x
    const DiscWallsInput t = walls_of(*transform(in, Relation::permute_axes, p));
    EXPECT_EQ(t.disc, (Disc{{2, 1}, 0.5})) << p;
    EXPECT_EQ(t.walls[0], (Wall{{4, 3}, {6, 5}})) << p;
  }
  for (int p : {0, 1, 4}) EXPECT_TRUE(*transform(in, Relation::permute_axes, p) == in) << p;
  EXPECT_EQ(walls_of(*transform(in, Relation::flip_axis, 0)).walls[0], (Wall{{-3, 4}, {-5, 6}}));
  EXPECT_EQ(walls_of(*transform(in, Relation::flip_axis, 1)).disc, (Disc{{1, -2}, 0.5}));
  EXPECT_TRUE(*transform(in, Relation::flip_axis, 2) == in);
  const DiscWallsInput scaled = walls_of(*transform(in, Relation::scale, 3));
  EXPECT_EQ(scaled.disc, (Disc{{8, 16}, 4}));
  EXPECT_EQ(scaled.walls[0], (Wall{{24, 32}, {40, 48}}));
  EXPECT_FALSE(transform(in, Relation::swap_shapes, 0));
  EXPECT_FALSE(transform(in, Relation::permute_faces, 1));
}

// Walls reordered: the same walls, some moved, and a wall touched (i, 0) renamed to where it
// went; a wall's ends swapped for some walls and not others, the walls staying where they are.
TEST(Transform, WallsAreReorderedAndTheirEndsSwapped) {
  DiscWallsInput in{{{0, 0}, 1}, {}};
  for (int i = 0; i < 9; ++i) in.walls.push_back({{static_cast<double>(i), 0}, {static_cast<double>(i), 1}});
  for (int parameter : {1, 77, 123456}) {
    const auto moved = std::get<DiscWallsInput>(*transform(in, Relation::permute_objects, parameter));
    EXPECT_EQ(moved.disc, in.disc);
    int displaced = 0;
    for (std::uint32_t i = 0; i < 9; ++i) {
      Answer one;
      one.pairs = {{i, 0}};
      const FacePair to = mapped_answer(one, in, Relation::permute_objects, parameter).pairs[0];
      EXPECT_EQ(to.second, 0u);
      EXPECT_EQ(moved.walls[to.first], in.walls[i]);
      displaced += to.first != i;
    }
    EXPECT_GT(displaced, 0);
    const auto swapped = std::get<DiscWallsInput>(*transform(in, Relation::permute_vertices, parameter));
    int reversed = 0;
    for (std::size_t i = 0; i < 9; ++i) {
      const Wall& w = swapped.walls[i];
      EXPECT_TRUE(w == in.walls[i] || (w.a == in.walls[i].b && w.b == in.walls[i].a)) << i;
      reversed += w != in.walls[i];
    }
    EXPECT_GT(reversed, 0);
    EXPECT_LT(reversed, 9);
    Answer all = Answer::of(true);
    all.pairs = {{2, 0}, {5, 0}};
    EXPECT_EQ(mapped_answer(all, in, Relation::permute_vertices, parameter), all);  // no wall renamed
  }
}

TEST(FlushExtremes, ZeroesTinyAndHugeValuesOnly) {
  const Input in = SphereSphereInput{{{0x1p-300, 0x1p260, 3}, 5e-324}, {{-0x1p-250, 0, 0}, 1}};
  const Input flushed = flush_extremes(in);
  const auto& out = std::get<SphereSphereInput>(flushed);
  EXPECT_EQ(out.a.center, (Vec3{0, 0, 3}));
  EXPECT_EQ(out.a.radius, 0);
  EXPECT_EQ(out.b.center.x, -0x1p-250);
}

}  // namespace
}  // namespace cc::harness
