// The bench binary: every suite, then the table of ratios (FCL time / library time, medians of
// repeated runs) and, with --json FILE, the same as JSON.
//
//   crosscheck_bench [--json FILE] [--campaign-json FILE] [--cpu-time] [Google Benchmark flags...]
//
// --campaign-json reads the output of `crosscheck campaign --json` and adds the harness's
// cases/s to the table. --cpu-time takes the medians of the process's CPU time instead of the
// wall-clock time: on a shared machine, time slices given to other processes do not add to it.
// Unless given, --benchmark_repetitions=5 and --benchmark_min_time=0.1.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "bench/collector.h"
#include "bench/inputs.h"
#include "bench/ratio_table.h"
#include "bench/suites.h"

namespace {

struct Args {
  std::string json, campaign_json;
  bool cpu_time = false;
  std::vector<std::string> passed;  // to Google Benchmark
};

Args parse(int argc, char** argv) {
  Args a;
  a.passed.push_back(argv[0]);
  bool repetitions = false, min_time = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&](const char* flag, std::string& out) {
      const std::string eq = std::string(flag) + "=";
      if (arg == flag && i + 1 < argc) return out = argv[++i], true;
      if (arg.rfind(eq, 0) == 0) return out = arg.substr(eq.size()), true;
      return false;
    };
    if (value("--json", a.json) || value("--campaign-json", a.campaign_json)) continue;
    if (arg == "--cpu-time") {
      a.cpu_time = true;
      continue;
    }
    repetitions |= arg.rfind("--benchmark_repetitions", 0) == 0;
    min_time |= arg.rfind("--benchmark_min_time", 0) == 0;
    a.passed.push_back(arg);
  }
  if (!repetitions) a.passed.push_back("--benchmark_repetitions=5");
  if (!min_time) a.passed.push_back("--benchmark_min_time=0.1");
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  Args args = parse(argc, argv);
  std::vector<char*> gb_argv;
  for (std::string& s : args.passed) gb_argv.push_back(s.data());
  int gb_argc = static_cast<int>(gb_argv.size());
  benchmark::Initialize(&gb_argc, gb_argv.data());
  if (benchmark::ReportUnrecognizedArguments(gb_argc, gb_argv.data())) return 2;

  nlohmann::json campaign;
  if (!args.campaign_json.empty()) {
    std::ifstream in(args.campaign_json);
    try {
      campaign = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "crosscheck_bench: cannot read %s: %s\n", args.campaign_json.c_str(), e.what());
      return 2;
    }
  }

  std::fprintf(stderr, "bench: seed %llu (CROSSCHECK_BENCH_SEED overrides it); generating inputs\n",
               static_cast<unsigned long long>(cc::bench::seed()));
  cc::bench::register_primitive_benchmarks();
  cc::bench::register_ray_benchmarks();
  cc::bench::register_hierarchy_benchmarks();
  cc::bench::register_broadphase_benchmarks();

  cc::bench::Collector collector(args.cpu_time);
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  const auto rows = cc::bench::make_rows(collector.results(), campaign);
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::localtime(&now));
  std::printf("crosscheck bench, %s, seed %llu: medians of repeated runs (%s); FCL / library > 1 means the library is faster\n",
              date, static_cast<unsigned long long>(cc::bench::seed()), args.cpu_time ? "CPU time" : "wall-clock time");
  cc::bench::print_rows(rows, stdout);
  if (!args.json.empty()) {
    nlohmann::json j = cc::bench::rows_json(rows, collector.results());
    j["date"] = date;
    j["time"] = args.cpu_time ? "cpu" : "wall";
    j["seed"] = cc::bench::seed();
    if (!campaign.is_null()) j["campaign"] = campaign;
    std::ofstream out(args.json);
    out << j.dump(2) << "\n";
    if (!out) {
      std::fprintf(stderr, "crosscheck_bench: cannot write %s\n", args.json.c_str());
      return 2;
    }
  }
  return 0;
}
