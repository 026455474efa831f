// crosscheck: differential campaigns and case triage for the collision library.
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

#include "tool/commands.h"
#include "tool/flag_checks.h"
#include "tool/run_context.h"

namespace {

// The name of the subcommand given on the command line, or "" before one is known.
std::string command_name(const CLI::App& app) {
  const std::vector<CLI::App*> given = app.get_subcommands();
  return given.empty() ? "" : " " + given.front()->get_name();
}

bool is_subcommand(const CLI::App& app, const std::string& word) {
  for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (c->check_name(word)) return true;
  }
  return false;
}

// The command's exit status, once what it printed has reached standard output: a write that
// failed there (a full disk, a closed pipe) is an incomplete run (exit 3) with a message, unless
// the status already says worse.
int finished(const CLI::App& app, int exit_code) {
  errno = 0;
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return exit_code;
  const int error = errno;
  std::fprintf(stderr, "crosscheck%s: cannot write standard output%s%s\n", command_name(app).c_str(),
               error != 0 ? ": " : "", error != 0 ? std::strerror(error) : "");
  return exit_code == 0 || exit_code == cc::tool::kExitFound ? cc::tool::kExitIncomplete : exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"crosscheck: the collision library (or a subject) checked against FCL/libccd, Bullet, ODE, Chipmunk and exact rational arithmetic"};
  app.require_subcommand(1);
  app.set_version_flag("--version", cc::tool::version_line());
  app.footer("Query kinds: " + cc::tool::query_kind_names() +
             "\nExit status: 0 done, 1 an impl_bug found (or a replayed case changed), 2 bad input.");
  int exit_code = 0;
  cc::tool::add_campaign_command(app, exit_code);
  cc::tool::add_bands_command(app, exit_code);
  cc::tool::add_bounds_command(app, exit_code);
  cc::tool::add_triage_command(app, exit_code);
  cc::tool::add_shrink_command(app, exit_code);
  cc::tool::add_replay_command(app, exit_code);
  cc::tool::add_add_command(app, exit_code);
  cc::tool::add_fuzz_commands(app, exit_code);
  cc::tool::add_bvh_report_command(app, exit_code);
  cc::tool::add_scene_command(app, exit_code);
  cc::tool::add_car_command(app, exit_code);
  cc::tool::add_maze_command(app, exit_code);
  cc::tool::add_mutate_command(app, exit_code);
  cc::tool::add_kind_files_command(app, exit_code);
  cc::tool::add_audit_exact_command(app, exit_code);
  cc::tool::add_report_command(app, exit_code);
  cc::tool::add_fuzz_history_command(app, exit_code);
  if (argc > 1 && argv[1][0] != '-' && !is_subcommand(app, argv[1])) {
    std::fprintf(stderr, "crosscheck: unknown subcommand \"%s\" (crosscheck --help lists them)\n", argv[1]);
    return cc::tool::kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return finished(app, code == 0 ? 0 : cc::tool::kExitBadInput);
  } catch (const std::exception& e) {
    // A command that meets input it cannot use ends here, never in an abort.
    std::fprintf(stderr, "crosscheck%s: %s\n", command_name(app).c_str(), e.what());
    return finished(app, cc::tool::kExitBadInput);
  }
  return finished(app, exit_code);
}
