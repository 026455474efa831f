#include "oracle/fcl/fcl_scene.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "tool/scenes/rock_slide.h"

namespace cc::fcl_oracle {
namespace {

TEST(FclScene, EveryManagerFindsNaivesContacts) {
  harness::RockSlide slide({60, 2, 20});
  const Aabb world{{-100, -100, -100}, {100, 100, 100}};
  std::vector<std::vector<ObjectContact>> found;
  for (const std::string& name : FclScene::managers()) {
    FclScene scene(name, world);
    for (std::size_t i = 0; i < slide.size(); ++i) scene.add(slide.mesh_of(i), slide.pose_of(i));
    std::size_t candidates = 0;
    found.push_back(scene.collide(candidates));
    EXPECT_GE(candidates, found.back().size()) << name;
  }
  ASSERT_FALSE(found[0].empty());
  for (std::size_t m = 1; m < found.size(); ++m) {
    ASSERT_EQ(found[m].size(), found[0].size()) << FclScene::managers()[m];
    for (std::size_t i = 0; i < found[0].size(); ++i) {
      EXPECT_EQ(found[m][i].objects, found[0][i].objects);
      EXPECT_EQ(found[m][i].triangles, found[0][i].triangles);
    }
  }
}

TEST(FclScene, UnknownManagerIsRefused) {
  EXPECT_THROW(FclScene("Octree", Aabb{}), std::invalid_argument);
}

}  // namespace
}  // namespace cc::fcl_oracle
