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
  const std::optional<std::string> temporary = write_temporary_beside(path, text);
  if (!temporary) return failure(path, errno);
  if (::rename(temporary->c_str(), path.c_str()) == 0) return "";
  const int error = errno;
  ::unlink(temporary->c_str());
  return failure(path, error);
}

std::optional<std::string> write_temporary_beside(const std::filesystem::path& path, std::string_view text) {
  std::string temporary = (path.has_parent_path() ? path.parent_path() / "" : std::filesystem::path()).string() + "." +
                          path.filename().string() + ".XXXXXX";
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) return std::nullopt;
  bool written = harness::write_all(fd, text) && ::fsync(fd) == 0;
  int error = errno;
  if (::close(fd) != 0 && written) written = false, error = errno;
  if (written) return temporary;
  ::unlink(temporary.c_str());
  errno = error;
  return std::nullopt;
}

}  // namespace cc::tool
