// A Google Benchmark reporter that keeps, for every benchmark, the median over its repetitions
// of the time per item, and prints one line per benchmark as it finishes.
#pragma once

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace cc::bench {

/// One benchmark's result: medians over the repetitions that ran without error.
struct Measured {
  double ns_per_item = 0;  // real (or CPU) time per iteration / counter items_per_iter (1 if absent)
  int repetitions = 0;
  std::map<std::string, double> counters;  // medians of the user counters
};

/// Collects results by registered name (e.g. "obb_obb/mixed/lib").
class Collector final : public benchmark::BenchmarkReporter {
 public:
  /// cpu_time: the process's CPU time per iteration instead of the wall-clock time.
  explicit Collector(bool cpu_time = false) : cpu_time_(cpu_time) {}
  bool ReportContext(const Context& context) override;
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override;
  /// The medians, by name; complete after RunSpecifiedBenchmarks returns.
  const std::map<std::string, Measured>& results() const { return results_; }

 private:
  void flush(const std::string& name);
  std::map<std::string, std::vector<Run>> pending_;
  std::map<std::string, Measured> results_;
  bool cpu_time_;
};

}  // namespace cc::bench
