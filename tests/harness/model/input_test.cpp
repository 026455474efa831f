// The inputs of every kind: which kinds ask what of two placed meshes (pairs, or their
// distance), and which is asked of boxes over frames or of a disc against walls, found in the
// registry.
#include "harness/model/input.h"

#include <gtest/gtest.h>

#include <set>

namespace cc::harness {
namespace {

TEST(Input, TheMeshKindsSayWhatTheyAskAndAreFoundByIt) {
  std::set<CollisionMode> asked;
  for (QueryKind kind : kAllQueryKinds) {
    const Input in = with_kind(kind, []<class In>() -> Input { return In{}; });
    const std::optional<CollisionMode> mode = mesh_mode_of(in);
    // Every kind of two meshes asks for their pairs, but the one that asks for their distance.
    EXPECT_EQ(mode.has_value() || kind == QueryKind::mesh_mesh_distance, meshes_of(in) != nullptr) << name(kind);
    if (!mode) continue;
    EXPECT_TRUE(asked.insert(*mode).second) << name(kind) << ": two mesh kinds ask the same";
    EXPECT_EQ(mesh_kind(*mode), kind) << name(kind);
  }
  EXPECT_EQ(asked, (std::set<CollisionMode>{CollisionMode::all_pairs, CollisionMode::first_hit}));
  EXPECT_EQ(mesh_kind(CollisionMode::all_pairs), QueryKind::mesh_mesh);
  EXPECT_EQ(mesh_kind(CollisionMode::first_hit), QueryKind::mesh_mesh_first);
}

TEST(Input, BoxesOverFramesMakeTheInputOfTheirKind) {
  const Aabb box{{0, 0, 0}, {1, 2, 3}};
  const BoxFrames frames = {{box, std::nullopt}, {std::nullopt, box}};
  const Input in = box_frames_input(frames);
  EXPECT_EQ(kind_of(in), QueryKind::broadphase);
  EXPECT_EQ(std::get<BroadphaseInput>(in).frames, frames);
  EXPECT_TRUE(std::get<BroadphaseInput>(box_frames_input({})).frames.empty());
}

TEST(Input, ADiscAndWallsMakeTheInputOfTheirKind) {
  const Disc disc{{1, 2}, 0.5};
  const std::vector<Wall> walls = {{{0, 0}, {3, 0}}, {{1, 1}, {1, 1}}};
  const Input in = disc_and_walls_input(disc, walls);
  EXPECT_EQ(kind_of(in), QueryKind::disc_walls);
  EXPECT_TRUE((in == Input{DiscWallsInput{disc, walls}}));
}

}  // namespace
}  // namespace cc::harness
