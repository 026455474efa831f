// Writing a command's output file (--json, --svg, --boxes-case): "-" is standard output; a file
// is written whole or not at all.
#pragma once

#include <string>
#include <string_view>

namespace cc::tool {

/// Writes `text` to `path`: "-" means standard output (flushed); a regular file (new or not) is
/// written to a temporary file beside it and renamed over it, so that a failed write (a full
/// disk) leaves what was there and no partial file; anything else that exists (a device, a
/// FIFO) is written in place. Returns "" on success, else a sentence naming the file and the
/// reason ("cannot write out.json: No space left on device").
std::string write_output_file(const std::string& path, std::string_view text);

}  // namespace cc::tool
