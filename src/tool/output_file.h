// Writing a command's output file (--json, --svg, --boxes-case): "-" is standard output; a file
// is written whole or not at all.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace cc::tool {

/// Writes `text` to `path`: "-" means standard output (flushed); a regular file (new or not) is
/// written to a temporary file beside it and renamed over it, so that a failed write (a full
/// disk) leaves what was there and no partial file; anything else that exists (a device, a
/// FIFO) is written in place. Returns "" on success, else a sentence naming the file and the
/// reason ("cannot write out.json: No space left on device").
std::string write_output_file(const std::string& path, std::string_view text);

/// Writes `text` whole to a new temporary file beside `path` (".NAME.XXXXXX" in its folder) and
/// syncs it, for the caller to rename or link into place. Returns the temporary's path; nothing
/// when it failed (errno set, no file left).
std::optional<std::string> write_temporary_beside(const std::filesystem::path& path, std::string_view text);

}  // namespace cc::tool
