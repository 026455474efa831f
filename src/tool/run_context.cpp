#include "tool/run_context.h"

#include <fstream>
#include <thread>

#include "oracle/bullet/bullet_oracle.h"
#include "oracle/chipmunk/chipmunk_oracle.h"
#include "oracle/fcl/fcl_oracle.h"
#include "oracle/ode/ode_oracle.h"
#include "tool/history.h"
#include "tool/version.h"

namespace cc::tool {

std::string version_line() {
  return std::string("crosscheck ") + CROSSCHECK_VERSION + " (commit " + CROSSCHECK_COMMIT + "), FCL " +
         std::string(fcl_oracle::fcl_version()) + ", Bullet " + std::string(bullet_oracle::bullet_version()) + ", ODE " +
         std::string(ode_oracle::ode_version()) + ", Chipmunk " + std::string(chipmunk_oracle::chipmunk_version());
}

nlohmann::json versions_json() {
  return {{"crosscheck", CROSSCHECK_VERSION},
          {"commit", CROSSCHECK_COMMIT},
          {"FCL", fcl_oracle::fcl_version()},
          {"Bullet", bullet_oracle::bullet_version()},
          {"ODE", ode_oracle::ode_version()},
          {"Chipmunk", chipmunk_oracle::chipmunk_version()}};
}

std::string processor_description() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown processor";
  while (std::getline(cpuinfo, line)) {
    if (line.starts_with("model name")) {
      if (const auto colon = line.find(':'); colon != std::string::npos && colon + 2 <= line.size()) model = line.substr(colon + 2);
      break;
    }
  }
  const unsigned threads = std::thread::hardware_concurrency();
  return model + ", " + (threads > 0 ? std::to_string(threads) : std::string("unknown")) + " hardware threads";
}

nlohmann::json run_record(std::string_view run, std::time_t started, double seconds, const std::string& subject) {
  return {{"format", "crosscheck history"},
          {"version", kHistoryVersion},
          {"run", run},
          {"started", iso_utc(started)},
          {"seconds", seconds},
          {"versions", versions_json()},
          {"processor", processor_description()},
          {"subject", subject.empty() ? nlohmann::json(nullptr) : nlohmann::json(subject)}};
}

}  // namespace cc::tool
