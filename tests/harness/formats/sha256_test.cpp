// SHA-256 against the standard's examples: the empty message, one block, the two-block message
// whose padding spills into a second block, a million bytes, and a file's bytes.
#include "harness/formats/sha256.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "temp_folder.h"

namespace cc::harness {
namespace {

TEST(Sha256, TheStandardsExamples) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, EveryLengthAroundABlockDiffers) {
  std::string previous;
  for (std::size_t n = 50; n < 140; ++n) {
    const std::string digest = sha256_hex(std::string(n, 'x'));
    EXPECT_EQ(digest.size(), 64u);
    EXPECT_NE(digest, previous) << n;
    previous = digest;
  }
}

TEST(Sha256, OfAFileAndOfNoFile) {
  const test::TempFolder folder("sha256");
  const auto file = folder.path() / "abc";
  std::ofstream(file) << "abc";
  EXPECT_EQ(sha256_of_file(file), sha256_hex("abc"));
  EXPECT_THROW(sha256_of_file(folder.path() / "missing"), std::runtime_error);
}

}  // namespace
}  // namespace cc::harness
