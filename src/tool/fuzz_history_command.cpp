// crosscheck fuzz-history: adds a night of fuzzing (fuzz/nightly.sh's report.json) to a history
// folder, as a record of run "fuzz" beside the campaigns', for `crosscheck report`.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "tool/commands.h"
#include "tool/flag_checks.h"
#include "tool/history.h"
#include "tool/run_context.h"

namespace cc::tool {
namespace {

using Json = nlohmann::json;

struct FuzzHistoryArgs {
  std::string report, history;
};

// A place in the report that is not what nightly.sh writes.
struct BadReport : std::runtime_error {
  BadReport(const std::string& where, const std::string& what) : std::runtime_error(where + ": " + what) {}
};

const Json& member(const Json& object, const std::string& where, const char* key, Json::value_t type) {
  const auto it = object.find(key);
  const std::string place = where + "/" + key;
  if (it == object.end()) throw BadReport(place, "missing");
  const bool number = type == Json::value_t::number_float;
  if (number ? !it->is_number() : it->type() != type) {
    throw BadReport(place, std::string("not ") + (number ? "a number" : Json(type).type_name()));
  }
  if (number && !(std::isfinite(it->get<double>()) && it->get<double>() >= 0)) {
    throw BadReport(place, "not a finite number >= 0");
  }
  return *it;
}

// The record of the night, from nightly.sh's report: "started", "seconds", "minutes", "jobs",
// "interrupted", "subject", per target its figures ("targets": execs_per_second, coverage and
// features before and after, findings per class), and "findings" (each: query, class,
// disagreement, group, case_file, as `fuzz-case` gave them). "queries" counts the findings per
// kind and class, as a campaign's record does.
Json fuzz_record(const Json& report) {
  if (!report.is_object()) throw BadReport("/", "not an object");
  const std::string started = member(report, "", "started", Json::value_t::string).get<std::string>();
  const auto start = from_iso_utc(started);
  if (!start) throw BadReport("/started", "\"" + started + "\" is not a time as 2026-12-02T19:50:00Z");
  const double seconds = member(report, "", "seconds", Json::value_t::number_float).get<double>();
  const std::string subject = member(report, "", "subject", Json::value_t::string).get<std::string>();
  Json record = run_record("fuzz", *start, seconds, subject);
  for (const char* key : {"minutes", "jobs"}) record[key] = member(report, "", key, Json::value_t::number_float);
  record["interrupted"] = member(report, "", "interrupted", Json::value_t::boolean);
  const Json& targets = member(report, "", "targets", Json::value_t::object);
  Json queries = Json::object();
  for (const auto& [target, figures] : targets.items()) {
    const std::string where = "/targets/" + target;
    if (!figures.is_object()) throw BadReport(where, "not an object");
    for (const char* key :
         {"seconds", "execs_per_second", "features_before", "features_after", "coverage_before", "coverage_after"}) {
      member(figures, where, key, Json::value_t::number_float);
    }
    member(figures, where, "status", Json::value_t::string);
    const Json& found = member(figures, where, "findings", Json::value_t::object);
    for (const auto& [cls, count] : found.items()) {
      member(found, where + "/findings", cls.c_str(), Json::value_t::number_float);
      queries[target][cls] = count;
    }
  }
  record["targets"] = targets;
  record["queries"] = queries;
  const Json& findings = member(report, "", "findings", Json::value_t::array);
  for (std::size_t i = 0; i < findings.size(); ++i) {
    const std::string where = "/findings/" + std::to_string(i);
    if (!findings[i].is_object()) throw BadReport(where, "not an object");
    for (const char* key : {"query", "class", "disagreement", "group", "case_file"}) {
      member(findings[i], where, key, Json::value_t::string);
    }
  }
  record["findings"] = findings;
  return record;
}

int run(const FuzzHistoryArgs& args) {
  std::string text;
  if (args.report == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  } else {
    std::ifstream in(args.report);
    if (!in) {
      std::fprintf(stderr, "crosscheck fuzz-history: %s: cannot read the file\n", args.report.c_str());
      return kExitBadInput;
    }
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string name = args.report == "-" ? "standard input" : args.report;
  Json record;
  try {
    record = fuzz_record(Json::parse(text));
  } catch (const Json::parse_error& e) {
    std::fprintf(stderr, "crosscheck fuzz-history: %s: not JSON (byte %zu): %s\n", name.c_str(), e.byte, e.what());
    return kExitBadInput;
  } catch (const BadReport& e) {
    std::fprintf(stderr, "crosscheck fuzz-history: %s: %s (not a report of fuzz/nightly.sh)\n", name.c_str(), e.what());
    return kExitBadInput;
  }
  try {
    std::printf("history: %s\n", add_to_history(args.history, record).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crosscheck fuzz-history: --history: %s\n", e.what());
    return kExitIncomplete;
  }
  return 0;
}

}  // namespace

void add_fuzz_history_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<FuzzHistoryArgs>();
  auto* cmd = app.add_subcommand("fuzz-history", "Add a night of fuzzing (fuzz/nightly.sh's report.json) to a history folder, for crosscheck report");
  cmd->add_option("report", args->report, "The night's report.json, or - for standard input")->required()->check(CLI::Validator(
      [](std::string& path) {
        if (path == "-" || std::filesystem::is_regular_file(path)) return std::string();
        return path + (std::filesystem::is_directory(path) ? ": is a folder" : ": no such file");
      },
      "FILE|-"));
  cmd->add_option("--history", args->history, "The history folder (created if missing; the record is a new file)")->required()->check(writable_folder());
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
