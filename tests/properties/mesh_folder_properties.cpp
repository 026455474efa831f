// The generators of the kinds with meshes (ray_mesh's and two_meshes'), given a mesh folder that
// lacks some of FCL's test meshes (env.obj alone, rob.obj alone, neither): a case names only the
// files the folder holds (ray_mesh may take env.obj alone, a pair of meshes needs both), the
// others' meshes drawn instead, and it reads back from its JSON as it was written. With both
// files the cases name them now and then, so a generator that stopped looking for them is seen
// too.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <filesystem>
#include <string>

#include "harness/formats/input_json.h"
#include "harness/formats/mesh_files.h"
#include "harness/generation/generate.h"
#include "properties/property.h"
#include "temp_folder.h"
#include "test_paths.h"

namespace cc::test {
namespace {

using namespace harness;
namespace fs = std::filesystem;

// A fresh folder (removed with the test) holding the named files of FCL's meshes.
struct MeshFolder {
  TempFolder folder;
  MeshFolder(const std::string& name, std::initializer_list<const char*> files) : folder("crosscheck_mesh_folder_" + name) {
    for (const char* f : files) fs::copy_file(fcl_mesh_folder() / f, folder.path() / f);
  }
  const fs::path& path() const { return folder.path(); }
};

bool names(const Input& input, const std::string& file) {
  return input_to_json(input).dump().find("/" + file + "\"") != std::string::npos;
}

TEST(MeshFolders, WithoutBothOfFclsMeshesEveryMeshIsDrawn) {
  const MeshFolder env_folder("env", {"env.obj"}), rob_folder("rob", {"rob.obj"}), empty_folder("none", {});
  const fs::path &env_only = env_folder.path(), &rob_only = rob_folder.path(), &neither = empty_folder.path();
  // The folders above them must not hold the other file: the generators look upward for it.
  ASSERT_FALSE(find_mesh_file("rob.obj", env_only)) << "a rob.obj above " << env_only;
  ASSERT_FALSE(find_mesh_file("env.obj", rob_only)) << "an env.obj above " << rob_only;
  const fs::path folders[] = {env_only, rob_only, neither, fcl_mesh_folder()};
  for (const QueryKind kind : kAllQueryKinds) {
    if (!builds_hierarchies(kind) || kind == QueryKind::broadphase) continue;
    int drawn[std::size(folders)] = {}, with_files = 0;
    const bool passed = check_property_with_choices(std::string(name(kind)) + " draws its meshes without FCL's", 300,
                                                    [&](Choices& c) {
      const std::size_t which = c.draw(std::size(folders));
      const Input input = generate(kind, c, {.mesh_folder = folders[which]});
      ++drawn[which];
      for (const char* file : {"env.obj", "rob.obj"}) {
        const bool named = names(input, file);
        RC_ASSERT(!named || fs::exists(folders[which] / file));
        with_files += named;
      }
      const Json json = input_to_json(input);
      RC_ASSERT(input_to_json(input_from_json(kind, json, "/inputs", corpus_case_folder())).dump() == json.dump());
    });
    EXPECT_TRUE(passed) << name(kind);
    for (const int n : drawn) EXPECT_GT(n, 0) << name(kind);
    EXPECT_GT(with_files, 0) << name(kind) << " never drew FCL's meshes from their folder";
  }
}

}  // namespace
}  // namespace cc::test
