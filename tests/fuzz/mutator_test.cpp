// The fuzz targets' custom mutator (fuzz/mutator.cpp), built here without libFuzzer: its fallback
// to libFuzzer's own mutation is a stub that leaves the input as it is.
#include "fuzz/fuzz_target.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "harness/formats/fuzz_record.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t*, std::size_t size, std::size_t) { return size; }

namespace cc::fuzz {
namespace {

using namespace harness;

// The frames that hold two boxes or more.
int crowded_frames(const BroadphaseInput& in) {
  return static_cast<int>(std::ranges::count_if(in.frames, [](const auto& frame) {
    return std::ranges::count_if(frame, [](const auto& box) { return box.has_value(); }) >= 2;
  }));
}

// A broadphase record whose frames hold one box at a time: moved to touch, a frame gets a second
// box against the one it has, and the record written back keeps it (the mutated record's own
// header, not the original's masks).
void expect_touch_kept(const BroadphaseInput& in) {
  ASSERT_EQ(crowded_frames(in), 0);
  const std::vector<std::uint8_t> record = encode_record(in);
  int crowded = 0, mutations = 0;
  for (unsigned seed = 0; seed < 400; ++seed) {
    std::vector<std::uint8_t> data = record;
    data.resize(record.size() + 4096);
    const std::size_t size = mutate(QueryKind::broadphase, data.data(), record.size(), data.size(), seed);
    ASSERT_LE(size, data.size());
    const auto out = std::get<BroadphaseInput>(decode_record(QueryKind::broadphase, {data.data(), size}));
    mutations += !(out == in);
    crowded += crowded_frames(out) > 0;
  }
  EXPECT_GT(mutations, 100);
  EXPECT_GT(crowded, 10) << "touch's second box was lost in the record written back";
}

TEST(Mutator, TouchKeepsTheSecondBoxItPutsIntoAFrame) {
  BroadphaseInput handed_over;
  handed_over.frames = {{Aabb{{0, 0, 0}, {1, 1, 1}}, std::nullopt}, {std::nullopt, Aabb{{4, 4, 4}, {5, 6, 7}}}};
  expect_touch_kept(handed_over);
}

TEST(Mutator, TouchKeepsTheSecondSlotItGivesAOneBoxScene) {
  BroadphaseInput one_box;
  one_box.frames = {{Aabb{{0, 0, 0}, {1, 2, 3}}}, {Aabb{{1, 1, 1}, {2, 3, 4}}}};
  expect_touch_kept(one_box);
}

}  // namespace
}  // namespace cc::fuzz
