#include "tool/flag_checks.h"

#include <fcntl.h>
#include <stdlib.h>
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
  if (std::filesystem::is_directory(path, ec)) return path.string() + " is a folder, not a file";
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::exists(folder, ec)) return "no folder " + folder.string() + " to write " + path.string() + " in";
  if (!std::filesystem::is_directory(folder, ec)) return folder.string() + " is not a folder";
  const bool existed = std::filesystem::exists(path, ec);
  // O_NONBLOCK: a FIFO without a reader is refused instead of waited on.
  const int fd = ::open(path.c_str(), O_NONBLOCK | (existed ? O_WRONLY : (O_WRONLY | O_CREAT | O_EXCL)), 0644);
  if (fd < 0) return "cannot write " + path.string() + ": " + system_error_text();
  ::close(fd);
  if (!existed) ::unlink(path.c_str());
  return "";
}

std::string unwritable_folder(const std::filesystem::path& path) {
  std::error_code ec;
  if (path.empty()) return "an empty path";
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
  return "";
}

CLI::Validator writable_file() {
  return CLI::Validator([](std::string& text) { return unwritable_file(text); }, "FILE (writable)");
}

CLI::Validator writable_folder() {
  return CLI::Validator([](std::string& text) { return unwritable_folder(text); }, "FOLDER (writable)");
}

}  // namespace cc::tool
