#include "harness/formats/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace cc::harness {

std::string read_input_file(const std::filesystem::path& path, std::uintmax_t limit, const std::string& noun) {
  // Opened without blocking (a FIFO with no writer), then looked at through the descriptor.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputFileError(std::string("cannot read the file: ") + std::strerror(errno));
  struct stat s {};
  const bool known = ::fstat(fd, &s) == 0;
  const int error = errno;
  const auto refuse = [fd](const std::string& why) {
    ::close(fd);
    throw InputFileError(why);
  };
  if (!known) refuse(std::string("cannot read the file: ") + std::strerror(error));
  if (S_ISDIR(s.st_mode)) refuse("a folder, not a " + noun);
  if (!S_ISREG(s.st_mode)) refuse("not a regular file (a device, a FIFO or a socket)");
  if (static_cast<std::uintmax_t>(s.st_size) > limit) {
    refuse(std::to_string(s.st_size) + " bytes, over the limit of " + std::to_string(limit >> 20) + " MiB");
  }
  std::string bytes(static_cast<std::size_t>(s.st_size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) refuse(std::string("cannot read the file: ") + std::strerror(errno));
    if (n == 0) break;  // it shrank meanwhile
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  bytes.resize(got);
  return bytes;
}

}  // namespace cc::harness
