// crosscheck: differential campaigns and case triage for the collision library.
#include <CLI/CLI.hpp>

#include <iostream>

#include "tool/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"crosscheck: the collision library checked against FCL/libccd and exact rational arithmetic"};
  app.require_subcommand(1);
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : cc::tool::kExitBadInput;
  }
  return exit_code;
}
