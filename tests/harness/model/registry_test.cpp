// The registry of query kinds: the enumeration, the names, the Input variant and CMake's list of
// kinds (the fuzz targets, the units' sources) all follow it.
#include "harness/model/registry.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "harness/model/input.h"

namespace cc::harness {
namespace {

TEST(Registry, NamesAreUniqueAndReadBack) {
  std::set<std::string_view> names;
  for (QueryKind kind : kAllQueryKinds) {
    EXPECT_TRUE(names.insert(name(kind)).second) << name(kind);
    EXPECT_EQ(query_kind_named(name(kind)), kind);
  }
  EXPECT_FALSE(query_kind_named("no_such_kind"));
}

TEST(Registry, TheInputVariantFollowsTheKinds) {
  for (QueryKind kind : kAllQueryKinds) {
    const Input in = with_kind(kind, []<class In>() -> Input { return In{}; });
    EXPECT_EQ(kind_of(in), kind) << name(kind);
  }
}

// CMake reads the same list (CMakeLists.txt): the fuzz targets and the units' sources.
TEST(Registry, CMakeReadsTheSameKinds) {
  std::istringstream cmake(CROSSCHECK_QUERY_KINDS);
  std::vector<std::string> listed;
  for (std::string kind; std::getline(cmake, kind, ',');) listed.push_back(kind);
  ASSERT_EQ(listed.size(), kAllQueryKinds.size());
  for (std::size_t i = 0; i < listed.size(); ++i) EXPECT_EQ(listed[i], name(kAllQueryKinds[i]));
}

}  // namespace
}  // namespace cc::harness
