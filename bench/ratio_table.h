// The summary of a bench run: FCL time / library time per benchmark pair, the absolute figures
// that have targets of their own (ray_aabb, bytes per triangle, growth, harness cases/s), and
// issue 7's target for each row with whether it is met.
#pragma once

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/collector.h"

namespace cc::bench {

struct Row {
  std::string section;  // primitives, ray_aabb, hierarchy build, hierarchy all pairs, broadphase, harness
  std::string name;     // e.g. "obb_obb/mixed"
  std::string unit;     // what library and fcl are in: "ns/test", "us/query", "ms/frame", "B/tri", ...
  double library = 0;   // the library's figure
  double fcl = -1;      // FCL's (or the compared contestant's), -1 when there is none
  double ratio = -1;    // fcl / library for times and bytes, -1 when there is no pair
  std::string target;   // issue 7's target for this row, empty when it has none
  int met = -1;         // 1 met, 0 not met, -1 no target
  std::string note;     // hit shares, pair counts, what was compared
};

/// The rows for the measured benchmarks, and for the campaign's JSON (crosscheck campaign
/// --json) when given (null otherwise).
std::vector<Row> make_rows(const std::map<std::string, Measured>& results, const nlohmann::json& campaign);

/// Prints the rows as a Markdown table, grouped by section.
void print_rows(const std::vector<Row>& rows, std::FILE* out);

/// The rows and the raw medians as JSON.
nlohmann::json rows_json(const std::vector<Row>& rows, const std::map<std::string, Measured>& results);

}  // namespace cc::bench
