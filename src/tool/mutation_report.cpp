#include "tool/mutation_report.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace cc::tool {
namespace {

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f s", s);
  return buf;
}

std::string percent(int part, int whole) {
  if (whole == 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f%%", 100.0 * part / whole);
  return buf;
}

// A table cell: a pipe is escaped (Markdown shows \| as |, in code spans too), a newline is a
// space.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') {
      out += "\\|";
    } else {
      out += c == '\n' ? ' ' : c;
    }
  }
  return out;
}

// `text` with every path under the run's source tree shown by its path in the repository, every
// path under its work folder as WORK/..., and the earlier reports it read by their file names.
std::string without_machine_paths(const MutationRun& run, std::string text) {
  for (const auto& [folder, shown] : {std::pair{run.source_folder, std::string()}, std::pair{run.work_folder, std::string("WORK/")}}) {
    if (folder.empty()) continue;
    const std::string prefix = folder.back() == '/' ? folder : folder + "/";
    for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at + shown.size())) {
      text.replace(at, prefix.size(), shown);
    }
  }
  // An earlier report kept outside both (beside the work folder, say) is named by its file name.
  for (const std::string& report : {run.resumed_from, run.first_catchers_from}) {
    if (!report.starts_with('/')) continue;
    const std::string name = std::filesystem::path(report).filename().string();
    for (std::size_t at = text.find(report); at != std::string::npos; at = text.find(report, at + name.size())) {
      text.replace(at, report.size(), name);
    }
  }
  return text;
}

}  // namespace

std::string_view to_string(MutantStatus s) {
  switch (s) {
    case MutantStatus::caught_by_ctest: return "caught by ctest";
    case MutantStatus::caught_by_campaign: return "caught by campaign";
    case MutantStatus::survived: return "SURVIVED";
    case MutantStatus::equivalent: return "equivalent";
    case MutantStatus::stale: return "STALE";
    case MutantStatus::build_failed: return "does not build";
    case MutantStatus::not_executable: return "not executable here";
    case MutantStatus::not_run: return "not run";
    case MutantStatus::error: return "ERROR";
  }
  return "?";
}

namespace {

void count_into(Score& s, const MutantResult& r) {
  if (r.status == MutantStatus::caught_by_ctest) ++s.counted, ++s.by_ctest, ++s.by_either;
  if (r.status == MutantStatus::caught_by_campaign) ++s.counted, ++s.by_either;
  if (r.status == MutantStatus::survived) ++s.counted;
}

constexpr std::string_view kLayers[] = {"library", "references", "harness", "tool", "other"};

}  // namespace

Score score_of(const MutationRun& run) {
  Score s;
  for (const MutantResult& r : run.results) count_into(s, r);
  return s;
}

std::string_view layer_of(std::string_view file) {
  if (file.starts_with("src/collide/")) return "library";
  if (file.starts_with("oracle/")) return "references";
  if (file.starts_with("src/harness/")) return "harness";
  if (file.starts_with("src/tool/")) return "tool";
  return "other";
}

std::vector<std::pair<std::string, Score>> scores_by_layer(const MutationRun& run) {
  std::vector<std::pair<std::string, Score>> out;
  for (const std::string_view layer : kLayers) {
    Score s;
    bool any = false;
    for (const MutantResult& r : run.results) {
      if (layer_of(r.mutant.file) != layer) continue;
      any = true;
      count_into(s, r);
    }
    if (any) out.emplace_back(std::string(layer), s);
  }
  return out;
}

std::string markdown_report(const MutationRun& run) {
  const Score s = score_of(run);
  std::string out;
  out += "# Mutation score\n\n";
  out += "Written by `crosscheck mutate`, which replaces it at each run; what it measures and how to read it: "
         "[testing.md](testing.md).\n\n";
  out += "- date: " + run.date + " UTC\n- commit: " + run.commit + "\n- processor: " + run.processor +
         "\n- command: `" + without_machine_paths(run, run.command) + "`\n";
  if (!run.resumed_from.empty()) {
    const auto carried = std::count_if(run.results.begin(), run.results.end(),
                                       [](const MutantResult& r) { return !r.from_run.empty(); });
    out += "- resumed from: `" + without_machine_paths(run, run.resumed_from) + "`, whose results for " + std::to_string(carried) +
           " mutants (on the same source) are carried over, each marked in its note\n";
  }
  out += "\n";
  if (!run.finished) out += "**Unfinished**: written while the run goes on; mutants not run yet are marked so.\n\n";
  out += "Catalogue `" + without_machine_paths(run, run.catalogue) + "`, " + std::to_string(run.results.size()) + " mutants; " +
         std::to_string(run.jobs) + " worker(s); checks in order: " +
         (run.first_catchers_from.empty() ? ""
                                          : "the test that caught the mutant in `" + without_machine_paths(run, run.first_catchers_from) +
                                                "` (alone), then ") +
         "ctest labels ";
  for (std::size_t i = 0; i < run.labels.size(); ++i) out += (i ? ", " : "") + run.labels[i];
  char line[256];
  std::snprintf(line, sizeof line,
                " (stop on the first failure; a test running past %g times its own time on the unmutated tree, "
                "and at least %g s, counts as failed)",
                run.time_limit_factor, run.time_limit_floor);
  out += line;
  if (run.campaign_seconds > 0) {
    std::snprintf(line, sizeof line, ", then `crosscheck campaign --query KIND --seconds %g --seed %llu`",
                  run.campaign_seconds, static_cast<unsigned long long>(run.campaign_seed));
    out += line;
  }
  out += ".\n\n";
  out += "| score | caught | of | |\n|---|---|---|---|\n";
  out += "| ctest alone | " + std::to_string(s.by_ctest) + " | " + std::to_string(s.counted) + " | " +
         percent(s.by_ctest, s.counted) + " |\n";
  out += "| ctest + campaign | " + std::to_string(s.by_either) + " | " + std::to_string(s.counted) + " | " +
         percent(s.by_either, s.counted) + " |\n\n";
  out += "| layer | caught by ctest | caught by ctest + campaign | of |\n|---|---|---|---|\n";
  for (const auto& [layer, ls] : scores_by_layer(run)) {
    out += "| " + layer + " | " + std::to_string(ls.by_ctest) + " (" + percent(ls.by_ctest, ls.counted) + ") | " +
           std::to_string(ls.by_either) + " (" + percent(ls.by_either, ls.counted) + ") | " + std::to_string(ls.counted) +
           " |\n";
  }
  out += "\n";
  int equivalent = 0, stale = 0, not_run = 0, build_failed = 0, errors = 0, not_executable = 0;
  for (const MutantResult& r : run.results) {
    not_executable += r.status == MutantStatus::not_executable;
    equivalent += r.status == MutantStatus::equivalent;
    stale += r.status == MutantStatus::stale;
    not_run += r.status == MutantStatus::not_run;
    build_failed += r.status == MutantStatus::build_failed;
    errors += r.status == MutantStatus::error;
  }
  out += "Left out of the score: " + std::to_string(equivalent) + " equivalent, " + std::to_string(stale) + " stale, " +
         std::to_string(build_failed) + " not building, " + std::to_string(not_run) + " not run (budget or interrupted), " +
         std::to_string(errors) + " runner errors, " + std::to_string(not_executable) +
         " not executable here (SIMD kernels this processor cannot run).\n\n";
  std::snprintf(line, sizeof line, "Setup (sync, configure, build, baseline) %.0f s; whole run %.0f s (budget %g min).\n\n",
                run.setup_seconds, run.seconds, run.budget_minutes);
  out += line;
  if (!run.baseline.empty()) {
    out += "Unmutated tree:";
    for (const auto& [label, secs] : run.baseline) out += " " + label + " " + seconds_text(secs) + ";";
    out += "\n\n";
  }
  if (!run.excluded_tests.empty()) {
    out += "Tests failing on the unmutated tree, left out of the mutant runs:";
    for (const std::string& t : run.excluded_tests) out += " `" + t + "`";
    out += "\n\n";
  }
  out += "| mutant | query | file | result | caught by | after | build | note |\n";
  out += "|---|---|---|---|---|---|---|---|\n";
  for (const MutantResult& r : run.results) {
    const bool caught = r.status == MutantStatus::caught_by_ctest || r.status == MutantStatus::caught_by_campaign;
    const bool ran = caught || r.status == MutantStatus::survived || r.status == MutantStatus::build_failed ||
                     r.status == MutantStatus::error;
    std::string by = caught ? r.check + ": " + r.test : "";
    std::string note = r.note;
    if (r.status == MutantStatus::equivalent) note = r.mutant.equivalent;
    if (note.empty()) note = r.mutant.description;
    if (!r.from_run.empty()) note += " (from the run of " + r.from_run + ")";
    note = without_machine_paths(run, note);
    out += "| `" + r.mutant.id + "` | " + r.mutant.query + " | " + cell(r.mutant.file) + " | " +
           std::string(to_string(r.status)) + " | " + cell(by) + " | " + (caught ? seconds_text(r.seconds_to_catch) : "") +
           " | " + (ran ? seconds_text(r.build_seconds) : "") + " | " + cell(note) + " |\n";
  }
  return out;
}

std::string json_report(const MutationRun& run) {
  using Json = nlohmann::ordered_json;
  const Score s = score_of(run);
  Json j;
  j["date"] = run.date;
  j["command"] = run.command;
  j["commit"] = run.commit;
  j["changes"] = run.changes;
  j["processor"] = run.processor;
  j["catalogue"] = run.catalogue;
  j["jobs"] = run.jobs;
  j["budget_minutes"] = run.budget_minutes;
  j["campaign_seconds"] = run.campaign_seconds;
  j["campaign_seed"] = run.campaign_seed;
  j["labels"] = run.labels;
  j["baseline_seconds"] = Json::object();
  for (const auto& [label, secs] : run.baseline) j["baseline_seconds"][label] = secs;
  j["excluded_tests"] = run.excluded_tests;
  j["test_time_limit"] = {{"factor_of_own_time", run.time_limit_factor}, {"floor_seconds", run.time_limit_floor}};
  j["setup_seconds"] = run.setup_seconds;
  j["seconds"] = run.seconds;
  j["finished"] = run.finished;
  j["resumed_from"] = run.resumed_from;
  j["first_catchers_from"] = run.first_catchers_from;
  j["score"] = {{"counted", s.counted},
                {"caught_by_ctest", s.by_ctest},
                {"caught_by_ctest_or_campaign", s.by_either},
                {"ctest_fraction", s.counted ? double(s.by_ctest) / s.counted : 0.0},
                {"ctest_or_campaign_fraction", s.counted ? double(s.by_either) / s.counted : 0.0}};
  j["score_by_layer"] = Json::object();
  for (const auto& [layer, ls] : scores_by_layer(run)) {
    j["score_by_layer"][layer] = {{"counted", ls.counted}, {"caught_by_ctest", ls.by_ctest}, {"caught_by_ctest_or_campaign", ls.by_either}};
  }
  j["mutants"] = Json::array();
  for (const MutantResult& r : run.results) {
    j["mutants"].push_back({{"id", r.mutant.id},
                            {"query", r.mutant.query},
                            {"file", r.mutant.file},
                            {"kernel", r.mutant.kernel},
                            {"description", r.mutant.description},
                            {"original", r.mutant.original},
                            {"replacement", r.mutant.replacement},
                            {"status", std::string(to_string(r.status))},
                            {"check", r.check},
                            {"test", r.test},
                            {"note", r.status == MutantStatus::equivalent ? r.mutant.equivalent : r.note},
                            {"seconds_to_catch", r.seconds_to_catch},
                            {"build_seconds", r.build_seconds},
                            {"seconds", r.seconds},
                            {"worker", r.worker},
                            {"from_run", r.from_run}});
  }
  return j.dump(2) + "\n";
}

namespace {

constexpr MutantStatus kStatuses[] = {MutantStatus::caught_by_ctest, MutantStatus::caught_by_campaign,
                                      MutantStatus::survived,        MutantStatus::equivalent,
                                      MutantStatus::stale,           MutantStatus::build_failed,
                                      MutantStatus::not_executable,  MutantStatus::not_run,
                                      MutantStatus::error};

// A field of a report, or std::runtime_error naming the file and the field's JSON pointer.
template <class T>
T field(const nlohmann::json& j, const nlohmann::json::json_pointer& at, const std::filesystem::path& path) {
  try {
    return j.at(at).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error(path.string() + ": " + at.to_string() + " is missing or of the wrong type");
  }
}

MutantStatus status_named(const std::string& name, const std::string& where) {
  for (const MutantStatus s : kStatuses) {
    if (to_string(s) == name) return s;
  }
  throw std::runtime_error(where + ": \"" + name + "\" is not a mutant's result");
}

}  // namespace

MutationRun read_json_report(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path.string() + ": not JSON (byte " + std::to_string(e.byte) + ")");
  }
  using P = nlohmann::json::json_pointer;
  MutationRun run;
  run.date = field<std::string>(j, P("/date"), path);
  run.commit = field<std::string>(j, P("/commit"), path);
  run.changes = j.value("changes", std::string());
  run.labels = field<std::vector<std::string>>(j, P("/labels"), path);
  run.campaign_seconds = field<double>(j, P("/campaign_seconds"), path);
  run.campaign_seed = field<std::uint64_t>(j, P("/campaign_seed"), path);
  const auto count = field<nlohmann::json>(j, P("/mutants"), path).size();
  for (std::size_t i = 0; i < count; ++i) {
    const std::string at = "/mutants/" + std::to_string(i);
    MutantResult r;
    r.mutant.id = field<std::string>(j, P(at + "/id"), path);
    r.mutant.query = field<std::string>(j, P(at + "/query"), path);
    r.mutant.file = field<std::string>(j, P(at + "/file"), path);
    r.mutant.description = field<std::string>(j, P(at + "/description"), path);
    // Reports from before the texts were written carry none: their results are not taken.
    r.mutant.original = j.at(P(at)).value("original", std::string());
    r.mutant.replacement = j.at(P(at)).value("replacement", std::string());
    r.status = status_named(field<std::string>(j, P(at + "/status"), path), path.string() + ": " + at + "/status");
    r.check = field<std::string>(j, P(at + "/check"), path);
    r.test = field<std::string>(j, P(at + "/test"), path);
    r.note = field<std::string>(j, P(at + "/note"), path);
    r.seconds_to_catch = field<double>(j, P(at + "/seconds_to_catch"), path);
    r.build_seconds = field<double>(j, P(at + "/build_seconds"), path);
    r.seconds = field<double>(j, P(at + "/seconds"), path);
    r.worker = field<int>(j, P(at + "/worker"), path);
    r.from_run = j.at(P(at)).value("from_run", std::string());
    run.results.push_back(std::move(r));
  }
  return run;
}

std::vector<std::size_t> carry_over(MutationRun& run, const MutationRun& earlier) {
  if (run.commit == "unknown" || earlier.commit == "unknown") {
    throw std::runtime_error("the source tree's commit is unknown (not in git), so the runs cannot be told the same");
  }
  if (earlier.commit != run.commit || earlier.changes != run.changes) {
    throw std::runtime_error("its run was on " + earlier.commit + (earlier.changes.empty() ? "" : " (" + earlier.changes + ")") +
                             ", the source is now at " + run.commit + (run.changes.empty() ? "" : " (" + run.changes + ")"));
  }
  const bool same_campaign = earlier.campaign_seconds == run.campaign_seconds && earlier.campaign_seed == run.campaign_seed;
  const bool same_checks = earlier.labels == run.labels && same_campaign;
  const auto runs_check = [&](const std::string& check) {
    if (check == "campaign") return run.campaign_seconds > 0 && same_campaign;
    return std::find(run.labels.begin(), run.labels.end(), check) != run.labels.end();
  };
  std::vector<std::size_t> carried;
  for (std::size_t i = 0; i < run.results.size(); ++i) {
    MutantResult& now = run.results[i];
    if (now.status != MutantStatus::not_run) continue;  // stale, equivalent, not executable here
    const auto before = std::find_if(earlier.results.begin(), earlier.results.end(), [&](const MutantResult& e) {
      return e.mutant.id == now.mutant.id && e.mutant.file == now.mutant.file && e.mutant.original == now.mutant.original &&
             e.mutant.replacement == now.mutant.replacement;
    });
    if (before == earlier.results.end()) continue;
    const bool caught = before->status == MutantStatus::caught_by_ctest || before->status == MutantStatus::caught_by_campaign;
    const bool holds = (caught && runs_check(before->check)) || before->status == MutantStatus::build_failed ||
                       (before->status == MutantStatus::survived && same_checks);
    if (!holds) continue;
    const Mutant mutant = now.mutant;
    now = *before;
    now.mutant = mutant;
    if (now.from_run.empty()) now.from_run = earlier.date;
    carried.push_back(i);
  }
  return carried;
}

std::map<std::string, Catcher> catchers_of(const MutationRun& earlier) {
  std::map<std::string, Catcher> out;
  for (const MutantResult& r : earlier.results) {
    if (r.status != MutantStatus::caught_by_ctest || r.check.empty()) continue;
    const std::string test = r.test.substr(0, r.test.find(" ("));
    if (!test.empty()) out[r.mutant.id] = {r.check, test};
  }
  return out;
}

}  // namespace cc::tool
