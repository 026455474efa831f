// reserve_large: the room asked for, the elements kept, and on Linux with transparent huge pages
// the kernel's record of the advice (the "hg" flag of the mapping in /proc/self/smaps).
#include "collide/large_arrays.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cc {
namespace {

TEST(LargeArrays, ReservesTheRoomAndKeepsTheElements) {
  std::vector<int> small{1, 2, 3};
  reserve_large(small, 100);
  EXPECT_GE(small.capacity(), 100u);
  EXPECT_EQ(small, (std::vector<int>{1, 2, 3}));
  std::vector<double> large;
  reserve_large(large, std::size_t{1} << 23);  // 64 MiB
  EXPECT_GE(large.capacity(), std::size_t{1} << 23);
  EXPECT_TRUE(large.empty());
}

// The VmFlags of the mapping holding `address`, from /proc/self/smaps; empty if none.
std::string vm_flags_of(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return {};
}

TEST(LargeArrays, ALargeReservationIsAdvisedHugePages) {
#if defined(__linux__)
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled")) GTEST_SKIP() << "no transparent huge pages";
  std::vector<double> large;
  reserve_large(large, std::size_t{1} << 23);  // 64 MiB: malloc maps it on its own
  const std::string flags = vm_flags_of(large.data() + (std::size_t{1} << 22));  // its middle
  ASSERT_FALSE(flags.empty());
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  std::vector<double> small;
  reserve_large(small, 1000);  // under 2 MiB: no advice, the heap's mapping untouched
  EXPECT_EQ(vm_flags_of(small.data()).find(" hg"), std::string::npos);
#else
  GTEST_SKIP() << "Linux only";
#endif
}

}  // namespace
}  // namespace cc
