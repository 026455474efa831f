// Mesh files named by case files: find_mesh_file looks next to the case, then in the folders
// above it, takes absolute paths as they are and gives nothing for a missing file;
// load_mesh_file reads a file once and shares it, and refuses bad files; mesh_folder.
#include "harness/formats/mesh_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "harness/formats/obj_file.h"
#include "temp_folder.h"

namespace cc::harness {
namespace {

const std::filesystem::path kSource = (std::filesystem::path(CROSSCHECK_TEST_DATA) / ".." / "..").lexically_normal();
const std::filesystem::path kCorpora = kSource / "corpora";
const std::filesystem::path kBadMeshes = kSource / "tests" / "data" / "bad_meshes";

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

// A fresh folder for this test, removed with it.
struct TempDir : test::TempFolder {
  TempDir() : TempFolder("crosscheck_mesh_files_test") {}
};

TEST(MeshFiles, FindsCorporaMeshesFromAQueryFolderByWalkingUp) {
  ASSERT_TRUE(std::filesystem::is_directory(kCorpora / "obb_obb"));
  const auto found = find_mesh_file("meshes/env.obj", kCorpora / "obb_obb");
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(std::filesystem::equivalent(*found, kCorpora / "meshes" / "env.obj")) << *found;
}

TEST(MeshFiles, FindsAFileInTheCaseFolderBeforeOneAbove) {
  const TempDir dir;
  const auto near = dir.write("cases/mesh_mesh/m.obj", kTriangle);
  dir.write("cases/m.obj", kTriangle);
  const auto found = find_mesh_file("m.obj", dir.path() / "cases" / "mesh_mesh");
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(std::filesystem::equivalent(*found, near)) << *found;
}

TEST(MeshFiles, FindsTheNearestFolderAboveThatHasTheFile) {
  const TempDir dir;
  dir.write("meshes/m.obj", kTriangle);
  const auto nearer = dir.write("a/meshes/m.obj", kTriangle);
  std::filesystem::create_directories(dir.path() / "a" / "b" / "c");
  const auto found = find_mesh_file("meshes/m.obj", dir.path() / "a" / "b" / "c");
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(std::filesystem::equivalent(*found, nearer)) << *found;
}

TEST(MeshFiles, TakesAnAbsolutePathAsItIs) {
  const TempDir dir;
  const auto file = dir.write("elsewhere/m.obj", kTriangle);
  dir.write("cases/elsewhere/m.obj", kTriangle);  // not looked for: the path is absolute
  ASSERT_TRUE(file.is_absolute());
  EXPECT_EQ(find_mesh_file(file.string(), dir.path() / "cases"), file);
  EXPECT_EQ(find_mesh_file((dir.path() / "elsewhere" / "none.obj").string(), dir.path() / "cases"), std::nullopt);
}

TEST(MeshFiles, GivesNothingForAMissingFile) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path() / "cases");
  EXPECT_EQ(find_mesh_file("meshes/crosscheck_no_such_mesh_file.obj", dir.path() / "cases"), std::nullopt);
  EXPECT_EQ(find_mesh_file("crosscheck_no_such_mesh_file.obj", kCorpora / "obb_obb"), std::nullopt);
}

TEST(MeshFiles, LoadsAFileOnceAndSharesIt) {
  const auto first = load_mesh_file(kCorpora / "meshes" / "rob.obj");
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(*first, read_obj_file(kCorpora / "meshes" / "rob.obj"));
  EXPECT_EQ(load_mesh_file(kCorpora / "meshes" / "rob.obj"), first);
  // The same file by another spelling of its path.
  EXPECT_EQ(load_mesh_file(kCorpora / "obb_obb" / ".." / "meshes" / "rob.obj"), first);
  EXPECT_NE(load_mesh_file(kCorpora / "meshes" / "env.obj"), first);
}

TEST(MeshFiles, RefusesABadFileEveryTime) {
  const auto path = kBadMeshes / "nan_coordinate.obj";
  EXPECT_THROW(load_mesh_file(path), MeshFileError);
  EXPECT_THROW(load_mesh_file(path), MeshFileError);  // a failure is not cached as a mesh
  EXPECT_THROW(load_mesh_file(kBadMeshes / "no_such_file.obj"), MeshFileError);
}

TEST(MeshFiles, MeshFolderIsMeshesUnderTheCorporaRoot) {
  EXPECT_EQ(mesh_folder("/x/corpora"), std::filesystem::path("/x/corpora/meshes"));
  EXPECT_EQ(mesh_folder(kCorpora), kCorpora / "meshes");
  EXPECT_TRUE(std::filesystem::exists(mesh_folder(kCorpora) / "env.obj"));
}

}  // namespace
}  // namespace cc::harness
