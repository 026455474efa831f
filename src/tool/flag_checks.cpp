#include "tool/flag_checks.h"

#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>

#include "harness/model/query_kind.h"

namespace cc::tool {
namespace {

// The number the whole text spells, or nothing (trailing characters, no digits, out of range).
template <class T>
std::optional<T> whole_text(const std::string& text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string got(const std::string& text) { return "; got \"" + text + "\""; }

// The text of errno, for a probe that failed.
std::string system_error_text() { return std::strerror(errno); }

// Less free space than this where output goes is refused up front: a run would end with
// nothing stored.
constexpr unsigned long long kLeastFreeBytes = 1 << 20;

// Why `path` cannot be reached at all, or "": longer than the system allows (the whole path or
// one name), a name on the way that cannot be looked at (no permission), or a symbolic link on
// the way that loops, leads nowhere or cannot be followed. Names that do not exist yet are fine
// (they will be made), and so is a name under a file (the caller says it is no folder).
std::string unreachable(const std::filesystem::path& path) {
  const std::string whole = std::filesystem::absolute(path).string();
  if (whole.size() >= PATH_MAX) {
    return "the path is " + std::to_string(whole.size()) + " characters long, over the system's limit of " +
           std::to_string(PATH_MAX - 1);
  }
  for (const auto& name : path) {
    if (name.string().size() > NAME_MAX) {
      return "the name \"" + name.string().substr(0, 20) + "...\" is " + std::to_string(name.string().size()) +
             " characters long, over the system's limit of " + std::to_string(NAME_MAX);
    }
  }
  std::filesystem::path prefix;
  for (const auto& name : path) {
    prefix /= name;
    struct stat link {};
    if (::lstat(prefix.c_str(), &link) != 0) {
      // Missing from here on (made later), or under a file (told by the caller); else unreachable.
      if (errno == ENOENT || errno == ENOTDIR) return "";
      return "cannot reach " + prefix.string() + ": " + system_error_text();
    }
    if (!S_ISLNK(link.st_mode)) continue;
    struct stat target {};
    if (::stat(prefix.c_str(), &target) == 0) continue;
    if (errno == ELOOP) return prefix.string() + " is a loop of symbolic links";
    const bool missing = errno == ENOENT;
    const std::string why = system_error_text();
    std::error_code ec;
    return prefix.string() + " is a symbolic link to " + std::filesystem::read_symlink(prefix, ec).string() +
           (missing ? ", which does not exist" : ", which cannot be reached: " + why);
  }
  return "";
}

// Why output cannot go to `where` for want of space on its disk (`disk`, as statvfs or fstatvfs
// tells, the first when it is nonzero: not known, and the writes will tell), or "".
std::string too_little_space(int known, const struct statvfs& disk, const std::filesystem::path& where) {
  if (known != 0) return "";
  const unsigned long long free_bytes = static_cast<unsigned long long>(disk.f_bavail) * disk.f_frsize;
  if (free_bytes >= kLeastFreeBytes) return "";
  return "only " + std::to_string(free_bytes) + " bytes are free on the disk of " + where.string() +
         " (at least 1 MiB is needed)";
}

}  // namespace

CLI::Validator finite_in(double lo, double hi) {
  const std::string range = "[" + number_text(lo) + ", " + number_text(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        const auto x = whole_text<double>(text);
        if (!x || !std::isfinite(*x) || *x < lo || *x > hi) return "must be a finite number in " + range + got(text);
        return "";
      },
      "NUMBER in " + range);
}

CLI::Validator finite_above(double lo, double hi) {
  const std::string range = "(" + number_text(lo) + ", " + number_text(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        const auto x = whole_text<double>(text);
        if (!x || !std::isfinite(*x) || *x <= lo || *x > hi) return "must be a finite number in " + range + got(text);
        return "";
      },
      "NUMBER in " + range);
}

CLI::Validator whole_in(std::int64_t lo, std::int64_t hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        const auto x = whole_text<std::int64_t>(text);
        if (!x || *x < lo || *x > hi) return "must be a whole number in " + range + got(text);
        return "";
      },
      "INT in " + range);
}

CLI::Validator seed_value() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (!whole_text<std::uint64_t>(text)) return "must be a whole number in [0, 2^64 - 1]" + got(text);
        return "";
      },
      "SEED in [0, 2^64 - 1]");
}

std::string query_kind_names() {
  std::string names;
  for (harness::QueryKind kind : harness::kAllQueryKinds) names += (names.empty() ? "" : ", ") + std::string(name(kind));
  return names;
}

CLI::Validator query_kind_name() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (!harness::query_kind_named(text)) return "unknown query kind \"" + text + "\" (one of: " + query_kind_names() + ")";
        return "";
      },
      "QUERY");
}

std::string unwritable_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (path.empty()) return "an empty path";
  if (path == "-") return "";  // standard output
  if (std::string why = unreachable(path); !why.empty()) return why;
  if (std::filesystem::is_directory(path, ec)) return path.string() + " is a folder, not a file";
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::exists(folder, ec)) return "no folder " + folder.string() + " to write " + path.string() + " in";
  if (!std::filesystem::is_directory(folder, ec)) return folder.string() + " is not a folder";
  const bool existed = std::filesystem::exists(path, ec);
  // O_NONBLOCK: a FIFO without a reader is refused instead of waited on.
  const int fd = ::open(path.c_str(), O_NONBLOCK | (existed ? O_WRONLY : (O_WRONLY | O_CREAT | O_EXCL)), 0644);
  if (fd < 0) return "cannot write " + path.string() + ": " + system_error_text();
  struct stat written {};
  const bool regular = ::fstat(fd, &written) == 0 && S_ISREG(written.st_mode);
  struct statvfs disk {};  // the disk the file is on, where a symbolic link leads too
  const int known = ::fstatvfs(fd, &disk);
  ::close(fd);
  if (!existed) ::unlink(path.c_str());
  return regular ? too_little_space(known, disk, path) : "";
}

std::string unwritable_folder(const std::filesystem::path& path) {
  std::error_code ec;
  if (path.empty()) return "an empty path";
  if (std::string why = unreachable(path); !why.empty()) return why;
  // The folder itself, or the nearest ancestor that exists (where create_directories starts).
  std::filesystem::path existing = path;
  while (!std::filesystem::exists(existing, ec)) {
    if (!existing.has_parent_path() || existing.parent_path() == existing) {
      existing = ".";
      break;
    }
    existing = existing.parent_path();
  }
  if (!std::filesystem::is_directory(existing, ec)) {
    return existing == path ? path.string() + " is a file, not a folder"
                            : "cannot make the folder " + path.string() + ": " + existing.string() + " is not a folder";
  }
  std::string probe = (existing / ".crosscheck-probe-XXXXXX").string();
  if (::mkdtemp(probe.data()) == nullptr) return "cannot write in " + existing.string() + ": " + system_error_text();
  ::rmdir(probe.c_str());
  struct statvfs disk {};
  const int known = ::statvfs(existing.c_str(), &disk);
  return too_little_space(known, disk, existing);
}

CLI::Validator writable_file() {
  return CLI::Validator([](std::string& text) { return unwritable_file(text); }, "FILE (writable)");
}

CLI::Validator writable_folder() {
  return CLI::Validator([](std::string& text) { return unwritable_folder(text); }, "FOLDER (writable)");
}

}  // namespace cc::tool
