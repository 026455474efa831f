// Writing bytes whole: more than a pipe holds while a reader drains it, and false (not a crash)
// when the reader has gone.
#include "harness/formats/write_all.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <string>
#include <thread>

namespace cc::harness {
namespace {

TEST(WriteAll, WritesMoreThanAPipeHoldsWhole) {
  int p[2];
  ASSERT_EQ(::pipe(p), 0);
  const std::string bytes(1 << 20, 'x');  // 16 times a pipe's default buffer: short writes happen
  std::string read;
  std::thread reader([&] {
    char buffer[4096];
    for (ssize_t n; (n = ::read(p[0], buffer, sizeof buffer)) > 0;) read.append(buffer, static_cast<std::size_t>(n));
  });
  EXPECT_TRUE(write_all(p[1], bytes));
  ::close(p[1]);
  reader.join();
  ::close(p[0]);
  EXPECT_EQ(read, bytes);
}

TEST(WriteAll, AReaderGoneIsFalse) {
  int p[2];
  ASSERT_EQ(::pipe(p), 0);
  ::close(p[0]);
  struct sigaction ignore {}, old {};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGPIPE, &ignore, &old);
  EXPECT_FALSE(write_all(p[1], "x"));
  ::sigaction(SIGPIPE, &old, nullptr);
  ::close(p[1]);
  EXPECT_TRUE(write_all(p[1], ""));  // nothing to write: nothing written, whatever the descriptor
}

}  // namespace
}  // namespace cc::harness
