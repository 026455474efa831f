// A history folder: one JSON record per run (a campaign, a night of fuzzing), each in a file of
// its own that is never overwritten, which `crosscheck report` turns into a page.
#pragma once

#include <nlohmann/json.hpp>

#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace cc::tool {

/// The version of the records' format this tool writes and reads.
inline constexpr int kHistoryVersion = 1;

/// The record's start as it says it: ISO 8601 in UTC, "2026-12-02T19:50:00Z".
std::string iso_utc(std::time_t t);

/// The time iso_utc wrote, or nothing for text it would not write (another form, a field out of
/// range, trailing characters).
std::optional<std::time_t> from_iso_utc(std::string_view text);

/// Adds the record (an object with "started", as iso_utc gives it, and "run") to the folder
/// (created if missing) as a new file named by its start and run,
/// e.g. "20261202T195000Z-campaign.json", or "...-campaign-2.json" when that name is taken: the
/// text is written whole to a temporary file and then linked to its name, which never replaces
/// a file. Returns the path; throws std::runtime_error with a sentence naming the folder or file
/// and the reason.
std::filesystem::path add_to_history(const std::filesystem::path& folder, const nlohmann::json& record);

}  // namespace cc::tool
