#include "tool/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "harness/formats/write_all.h"

namespace cc::tool {
namespace {

std::string failure(const std::string& path, int error) {
  return "cannot write " + (path == "-" ? std::string("standard output") : path) + ": " + std::strerror(error);
}

}  // namespace

std::string write_output_file(const std::string& path, std::string_view text) {
  if (path == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) return failure(path, errno);
    return "";
  }
  struct stat s {};
  if (::stat(path.c_str(), &s) == 0 && !S_ISREG(s.st_mode)) {  // a device or a FIFO: in place
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd < 0) return failure(path, errno);
    const bool written = harness::write_all(fd, text);
    const int error = errno;
    ::close(fd);
    return written ? "" : failure(path, error);
  }
  const std::filesystem::path target(path);
  std::string temporary = (target.has_parent_path() ? target.parent_path() / "" : std::filesystem::path()).string() + "." +
                          target.filename().string() + ".XXXXXX";
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) return failure(path, errno);
  bool written = harness::write_all(fd, text) && ::fsync(fd) == 0;
  int error = errno;
  written = ::close(fd) == 0 && written;
  if (written && ::rename(temporary.c_str(), path.c_str()) == 0) return "";
  if (written) error = errno;
  ::unlink(temporary.c_str());
  return failure(path, error);
}

}  // namespace cc::tool
