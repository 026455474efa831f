// Where and with what a run happened, as its reports and history records say it: the tool's
// version and commit, the versions of the peer libraries it asks, and the processor.
#pragma once

#include <nlohmann/json.hpp>

#include <ctime>
#include <string>
#include <string_view>

namespace cc::tool {

/// "crosscheck 0.1.0 (commit abc), FCL 0.7.0, Bullet 3.24, ODE 0.16.2, Chipmunk 7.0.3".
std::string version_line();

/// {"crosscheck": version, "commit": commit, "FCL": ..., "Bullet": ..., "ODE": ..., "Chipmunk": ...}.
nlohmann::json versions_json();

/// The processor's name (the first "model name" of /proc/cpuinfo) and the number of hardware
/// threads, or "unknown" for what cannot be read.
std::string processor_description();

/// What every history record (history.h) starts with: {"format": "crosscheck history",
/// "version", "run" (e.g. "campaign"), "started" (iso_utc), "seconds", "versions"
/// (versions_json()), "processor", "subject" (its path, or null)}. The run's own figures are added
/// beside them.
nlohmann::json run_record(std::string_view run, std::time_t started, double seconds, const std::string& subject);

}  // namespace cc::tool
