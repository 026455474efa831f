#include "tool/child_process.h"

#include <chrono>
#include <cstdio>
#include <system_error>

#include "harness/processes/child.h"
#include "harness/processes/interrupts.h"

namespace cc::tool {

void interrupt_children_on_signal() { harness::count_interrupts(); }

bool interrupted() { return harness::interrupts() > 0; }

double monotonic_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ChildResult run_child(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                      const std::filesystem::path& log, double timeout_seconds,
                      const std::filesystem::path& err_log, const std::function<bool()>& stop) {
  ChildResult result;
  const double start = monotonic_seconds();
  try {
    const harness::ChildEnd end = harness::run_program(argv, {cwd, log, err_log}, timeout_seconds,
                                                       [&stop] { return interrupted() || (stop && stop()); });
    result.exit_status = end.status;
    result.timed_out = end.timed_out;
    result.stopped = end.stopped;
  } catch (const std::system_error& e) {
    if (FILE* f = std::fopen(log.string().c_str(), "a")) {
      std::fprintf(f, "%s\n", e.what());
      std::fclose(f);
    }
    result.started = false;
  }
  result.seconds = monotonic_seconds() - start;
  return result;
}

}  // namespace cc::tool
