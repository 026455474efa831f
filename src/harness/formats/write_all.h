// Writing bytes to a file descriptor whole: what case files, output files, reports and the
// child processes' answers are written with.
#pragma once

#include <string_view>

namespace cc::harness {

/// Writes all of `bytes` to `fd`, retrying short writes and writes interrupted by a signal
/// (EINTR); false on any other error (a full disk, a closed pipe), with errno set by write.
bool write_all(int fd, std::string_view bytes);

}  // namespace cc::harness
