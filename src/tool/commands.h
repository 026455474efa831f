// The subcommands of the crosscheck tool, each registered on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

namespace cc::tool {

/// Exit codes: 0 success, 1 the run found an impl_bug (or a replay changed), 2 bad input, 3 the
/// run could not keep all it found (a case file not stored, a worker not started); a campaign
/// stopped by a signal exits 128 + its number once it has kept everything.
inline constexpr int kExitFound = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitIncomplete = 3;

void add_campaign_command(CLI::App& app, int& exit_code);
void add_bands_command(CLI::App& app, int& exit_code);
void add_bounds_command(CLI::App& app, int& exit_code);
void add_triage_command(CLI::App& app, int& exit_code);
void add_shrink_command(CLI::App& app, int& exit_code);
void add_replay_command(CLI::App& app, int& exit_code);
void add_add_command(CLI::App& app, int& exit_code);
void add_fuzz_commands(CLI::App& app, int& exit_code);
void add_bvh_report_command(CLI::App& app, int& exit_code);
void add_scene_command(CLI::App& app, int& exit_code);
void add_car_command(CLI::App& app, int& exit_code);
void add_maze_command(CLI::App& app, int& exit_code);
void add_mutate_command(CLI::App& app, int& exit_code);
void add_kind_files_command(CLI::App& app, int& exit_code);
void add_audit_exact_command(CLI::App& app, int& exit_code);
void add_report_command(CLI::App& app, int& exit_code);
void add_fuzz_history_command(CLI::App& app, int& exit_code);

}  // namespace cc::tool
