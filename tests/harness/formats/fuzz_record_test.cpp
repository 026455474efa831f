// The fuzz record round-trips every field: inputs whose values all differ (so that a field read
// into another's place, or two fields swapped, shows), with random shapes within what a record
// holds, for every query kind.
#include "harness/formats/fuzz_record.h"

#include <gtest/gtest.h>

#include "harness/formats/input_json.h"
#include "harness/formats/distinct_inputs.h"

namespace cc::harness {
namespace {

// The values bit for bit, and what is left when they are zeroed (shape, k, options, masks).
void expect_same(Input expected, Input actual, const std::string& what) {
  const std::string text = input_to_json(expected).dump();
  EXPECT_EQ(test::value_bits(actual), test::value_bits(expected)) << what << ": " << text;
  EXPECT_TRUE(actual == expected) << what << ": the shape or an option changed: " << text;
}

TEST(FuzzRecord, EveryFieldOfEveryKindRoundTrips) {
  for (QueryKind kind : kAllQueryKinds) {
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
      test::DistinctValues values(seed * 13 + static_cast<std::uint64_t>(kind));
      const Input in = test::distinct_input(kind, values, test::Reach::fuzz_record);
      const std::vector<std::uint8_t> bytes = encode_record(in);
      expect_same(in, decode_record(kind, bytes), std::string(name(kind)) + " through the bytes");
      expect_same(in, with_record_values(in, record_values(in)), std::string(name(kind)) + " through the values");
    }
  }
}

// The values come in the documented order (fuzz_record.h): each kind's first fields.
TEST(FuzzRecord, ValuesComeInTheDocumentedOrder) {
  const RayAabbInput ray{{{1, 2, 3}, {4, 5, 6}, 7, 8}, {{9, 10, 11}, {12, 13, 14}}};
  EXPECT_EQ(record_values(ray), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14}));
  const SphereSphereInput spheres{{{1, 2, 3}, 4}, {{5, 6, 7}, 8}};
  EXPECT_EQ(record_values(spheres), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}));
  const ObbObbInput obbs{{{1, 2, 3}, {4, 5, 6}, Mat3::from_columns({7, 8, 9}, {10, 11, 12}, {13, 14, 15})}, {}};
  const std::vector<double> v = record_values(obbs);
  EXPECT_EQ(std::vector<double>(v.begin(), v.begin() + 15),
            (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}));
  // The bytes: the tag, then little-endian doubles.
  const std::vector<std::uint8_t> bytes = encode_record(spheres);
  ASSERT_EQ(bytes.size(), 1 + 8 * 8u);
  EXPECT_EQ(bytes[0], static_cast<std::uint8_t>(QueryKind::sphere_sphere));
  EXPECT_EQ(bytes[8], 0x3f);  // 1.0 = 0x3ff0000000000000, most significant byte last
  EXPECT_EQ(bytes[7], 0xf0);
  // A disc (centre, radius), then the walls: a header byte (1 + b % 8 walls), each a, b.
  const DiscWallsInput maze{{{1, 2}, 3}, {{{4, 5}, {6, 7}}, {{8, 9}, {10, 11}}}};
  EXPECT_EQ(record_values(maze), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  const std::vector<std::uint8_t> walls = encode_record(maze);
  ASSERT_EQ(walls.size(), 2 + 8 * 11u);
  EXPECT_EQ(walls[0], static_cast<std::uint8_t>(QueryKind::disc_walls));
  EXPECT_EQ(walls[1], 1);  // two walls
  EXPECT_EQ(std::get<DiscWallsInput>(decode_record(QueryKind::disc_walls, {walls.data(), 2})).walls.size(), 2u);
  // Nine walls and more are recorded as their first eight.
  const DiscWallsInput many{{}, std::vector<Wall>(9, Wall{{1, 1}, {2, 2}})};
  EXPECT_EQ(std::get<DiscWallsInput>(decode_record(QueryKind::disc_walls, encode_record(many))).walls.size(), 8u);
}

}  // namespace
}  // namespace cc::harness
