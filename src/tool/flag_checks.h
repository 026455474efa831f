// Checks of the tool's flags, run by CLI11 before any command starts: a bad value ends the run
// with exit status 2 and "--flag: what is allowed". One home for every range, so that each
// command declares its limits instead of testing them in its own way.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace cc::tool {

/// A finite number in [lo, hi]. NaN and the infinities are refused (CLI::Range lets NaN
/// through: every comparison with it is false).
CLI::Validator finite_in(double lo, double hi);

/// A finite number greater than `lo` and at most `hi`: a duration that must be positive.
CLI::Validator finite_above(double lo, double hi);

/// A whole number in [lo, hi], written in decimal without a fraction.
CLI::Validator whole_in(std::int64_t lo, std::int64_t hi);

/// A seed: a decimal whole number in [0, 2^64 - 1]. A sign is refused (CLI11 itself would turn
/// "-1" into 2^64 - 1).
CLI::Validator seed_value();

/// The name of a query kind in the registry (harness/model/registry.h).
CLI::Validator query_kind_name();

/// The names of every query kind, comma-separated, in the registry's order.
std::string query_kind_names();

/// Why a file cannot be written at `path` (a folder there, a missing or unwritable folder
/// above it, a path or name longer than the system allows, a symbolic link on the way that
/// loops or leads nowhere, less than 1 MiB free on its disk), or "" when it can: checked by
/// creating the file (and removing it again unless it was there before). Nothing that exists
/// is changed. "-" (standard output) and devices (no disk to fill) can be written.
std::string unwritable_file(const std::filesystem::path& path);

/// Why a folder cannot be written at `path` (a file there or above it, no permission, the
/// length, symbolic links and free space as for a file), or "" when it can: the folder, or its
/// nearest existing ancestor, takes a probe that is removed.
std::string unwritable_folder(const std::filesystem::path& path);

/// Validators of the two above, for output flags.
CLI::Validator writable_file();
CLI::Validator writable_folder();

}  // namespace cc::tool
