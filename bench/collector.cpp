#include "bench/collector.h"

#include <algorithm>
#include <cstdio>

#include "harness/judging/median.h"

namespace cc::bench {
namespace {

double ns_per_unit(benchmark::TimeUnit unit) {
  switch (unit) {
    case benchmark::kNanosecond: return 1;
    case benchmark::kMicrosecond: return 1e3;
    case benchmark::kMillisecond: return 1e6;
    case benchmark::kSecond: break;
  }
  return 1e9;
}

}  // namespace

bool Collector::ReportContext(const Context& context) {
  std::fprintf(stderr, "bench: %d CPUs at %.0f MHz; medians of repeated runs follow as they finish\n",
               context.cpu_info.num_cpus, context.cpu_info.cycles_per_second / 1e6);
  return true;
}

void Collector::ReportRuns(const std::vector<Run>& runs) {
  for (const Run& run : runs) {
    if (run.run_type != Run::RT_Iteration) continue;  // aggregates are recomputed from the runs
    const std::string& name = run.run_name.function_name;
    if (run.error_occurred) {
      std::fprintf(stderr, "bench: %s failed: %s\n", name.c_str(), run.error_message.c_str());
      continue;
    }
    pending_[name].push_back(run);
    if (static_cast<int64_t>(pending_[name].size()) >= std::max<int64_t>(1, run.repetitions)) flush(name);
  }
}

void Collector::flush(const std::string& name) {
  const std::vector<Run>& runs = pending_[name];
  if (runs.empty()) return;
  std::vector<double> ns;
  std::map<std::string, std::vector<double>> counters;
  for (const Run& run : runs) {
    double items = 1;
    if (auto it = run.counters.find("items_per_iter"); it != run.counters.end() && it->second.value > 0) items = it->second.value;
    ns.push_back((cpu_time_ ? run.GetAdjustedCPUTime() : run.GetAdjustedRealTime()) * ns_per_unit(run.time_unit) / items);
    for (const auto& [key, counter] : run.counters) counters[key].push_back(counter.value);
  }
  Measured m;
  m.ns_per_item = harness::median(ns);
  m.repetitions = static_cast<int>(runs.size());
  for (auto& [key, values] : counters) m.counters[key] = harness::median(values);
  results_[name] = m;
  std::fprintf(stderr, "  %-44s %14.2f ns/item  (median of %d)\n", name.c_str(), m.ns_per_item, m.repetitions);
  pending_.erase(name);
}

void Collector::Finalize() {
  while (!pending_.empty()) flush(pending_.begin()->first);
}

}  // namespace cc::bench
