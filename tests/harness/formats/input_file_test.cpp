// Reading an input file whole: a regular file is read; a folder, a device (/dev/zero never ends),
// a FIFO with no writer and a file over the limit are refused at once, each with its reason.
#include "harness/formats/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <string>

#include "temp_folder.h"

namespace cc::harness {
namespace {

std::string refusal(const std::filesystem::path& path, std::uintmax_t limit = kMaxCaseFileBytes) {
  try {
    read_input_file(path, limit);
  } catch (const InputFileError& e) {
    return e.what();
  }
  return "(read)";
}

TEST(InputFile, ARegularFileIsReadWhole) {
  const test::TempFolder folder("input_file_read");
  EXPECT_EQ(read_input_file(folder.write("a.json", "{\"a\": 1}\n"), 100), "{\"a\": 1}\n");
  EXPECT_EQ(read_input_file(folder.write("empty", ""), 100), "");
}

TEST(InputFile, WhatIsNoRegularFileOrTooLargeIsRefusedAtOnce) {
  const test::TempFolder folder("input_file_refused");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(refusal(folder.path()), "a folder, not a file");
  EXPECT_EQ(refusal("/dev/zero"), "not a regular file (a device, a FIFO or a socket)");
  const auto fifo = folder.path() / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(refusal(fifo), "not a regular file (a device, a FIFO or a socket)");
  EXPECT_EQ(refusal(folder.write("big", std::string(2u << 20, 'x')), 1u << 20), "2097152 bytes, over the limit of 1 MiB");
  EXPECT_EQ(refusal(folder.write("limit", std::string(1u << 20, 'x')), 1u << 20), "(read)");
  EXPECT_NE(refusal(folder.path() / "missing").find("cannot read the file: No such file or directory"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
}

}  // namespace
}  // namespace cc::harness
