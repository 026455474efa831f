#include "tool/history.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <optional>
#include <stdexcept>

#include "tool/output_file.h"

namespace cc::tool {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& path, const std::string& what, int error) {
  throw std::runtime_error("cannot " + what + " " + path.string() + ": " + std::strerror(error));
}

}  // namespace

std::string iso_utc(std::time_t t) {
  std::tm parts{};
  gmtime_r(&t, &parts);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
  return text;
}

std::optional<std::time_t> from_iso_utc(std::string_view text) {
  std::tm parts{};
  const std::string copy(text);
  const char* end = strptime(copy.c_str(), "%Y-%m-%dT%H:%M:%SZ", &parts);
  if (end == nullptr || *end != '\0') return std::nullopt;
  const std::time_t t = timegm(&parts);
  if (iso_utc(t) != copy) return std::nullopt;  // e.g. 2026-02-30, 7-digit years, a missing 0
  return t;
}

fs::path add_to_history(const fs::path& folder, const nlohmann::json& record) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw std::runtime_error("cannot create the history folder " + folder.string() + ": " + error.message());
  const std::string started = record.at("started").get<std::string>(), run = record.at("run").get<std::string>();
  const auto is_one_of = [](const std::string& text, std::string_view allowed) {
    return !text.empty() && text.find_first_not_of(allowed) == std::string::npos;
  };
  if (!is_one_of(run, "abcdefghijklmnopqrstuvwxyz_") || !is_one_of(started, "0123456789-:TZ")) {
    throw std::runtime_error("cannot name a record of run \"" + run + "\" started \"" + started + "\" in " + folder.string());
  }
  std::string stem;  // 2026-12-02T19:50:00Z as 20261202T195000Z
  for (char c : started) {
    if (c != '-' && c != ':') stem += c;
  }
  stem += "-" + run;
  const std::optional<std::string> written = write_temporary_beside(folder / (stem + ".json"), record.dump(2) + "\n");
  if (!written) fail(folder, "write a record in", errno);
  const fs::path temporary = *written;
  for (int n = 1; n < 10000; ++n) {
    std::string name = stem;
    if (n > 1) name.append("-").append(std::to_string(n));  // (by append: GCC 12 warns falsely, -Wrestrict, on "-" + string)
    const fs::path path = folder / name.append(".json");
    if (link(temporary.c_str(), path.c_str()) == 0) {
      unlink(temporary.c_str());
      return path;
    }
    if (errno != EEXIST) {
      const int e = errno;
      unlink(temporary.c_str());
      fail(path, "write", e);
    }
  }
  unlink(temporary.c_str());
  throw std::runtime_error("cannot add a record to " + folder.string() + ": 9999 records of " + stem + " are there");
}

}  // namespace cc::tool
