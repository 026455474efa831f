// A scratch copy of the source tree kept in step file by file (crosscheck mutate's copies): new
// files copied with their time, changed ones rewritten (a change of the same size too), files
// gone removed, identical ones untouched, the build folder left out, and no copy inside the
// tree it copies.
#include "tool/scratch_tree.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "temp_folder.h"

namespace cc::tool {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SyncTree, KeepsTheCopyInStepFileByFile) {
  const test::TempFolder folder("crosscheck_sync_tree");
  const fs::path source = folder.path() / "source", copy = folder.path() / "copy";
  write(source / "a.cpp", "int a = 1;");
  write(source / "sub" / "b.h", "int b;");
  write(source / "gone.txt", "x");
  write(source / "build" / "output.o", "not copied");
  SyncCounts c = sync_tree(source, copy);
  EXPECT_EQ(c.created, 3);
  EXPECT_EQ(read(copy / "sub" / "b.h"), "int b;");
  EXPECT_EQ(fs::last_write_time(copy / "a.cpp"), fs::last_write_time(source / "a.cpp"));
  EXPECT_FALSE(fs::exists(copy / "build"));

  write(source / "a.cpp", "int a = 2;");  // the same size, another content
  fs::remove(source / "gone.txt");
  const auto untouched = fs::last_write_time(copy / "sub" / "b.h");
  c = sync_tree(source, copy);
  EXPECT_EQ(c.created, 0);
  EXPECT_EQ(c.updated, 1);
  EXPECT_EQ(c.removed, 1);
  EXPECT_EQ(read(copy / "a.cpp"), "int a = 2;");
  EXPECT_FALSE(fs::exists(copy / "gone.txt"));
  EXPECT_EQ(fs::last_write_time(copy / "sub" / "b.h"), untouched);
}

TEST(SyncTree, RefusesACopyInsideTheTreeOutsideItsBuildFolder) {
  const test::TempFolder folder("crosscheck_sync_inside");
  write(folder.path() / "a.cpp", "int a;");
  EXPECT_THROW(sync_tree(folder.path(), folder.path() / "scratch"), std::runtime_error);
  EXPECT_NO_THROW(sync_tree(folder.path(), folder.path() / "build" / "scratch"));
}

}  // namespace
}  // namespace cc::tool
