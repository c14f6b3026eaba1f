#pragma once
// --config FILE.yaml and --print-config, the same for every subcommand (../shared/DESIGN.md common
// options, docs/decisions/0017). A configuration file is a YAML map from option names to values:
// the long option without its dashes, '-' written '_' (`lidar_range_m: 6` is `--lidar-range-m 6`).
// Its keys are exactly the subcommand's named options that are settings: positional arguments
// and required options are the run's inputs and stay on the command line. A value goes through
// the same conversion and checks as on the command line, so the defaults stay where CLI11 reads
// them (the library's option structs, apps/tessera/commands.hpp); the command line wins over the
// file.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "tessera/core/result.hpp"

namespace tessera::cli {

/// Adds --config and --print-config to every subcommand of `app` that has no subcommands of its
/// own (eval relations, posegraph optimize, explore, ...).
void add_config_options(CLI::App& app);

/// The subcommand that runs: the innermost parsed one.
[[nodiscard]] CLI::App& parsed_leaf(CLI::App& app);

/// Sets every option of `command` that the command line left alone from `file`. Usage error, as
/// "FILE:LINE: key 'KEY': what is wrong", for a file that is not a YAML map, an unknown key, a
/// value of the wrong shape (a list for a single value) or one the option refuses (a word for a
/// number, a number out of range).
[[nodiscard]] Status apply_config_file(CLI::App& command, const std::filesystem::path& file);

/// The effective configuration as YAML that apply_config_file reads back: every setting with its
/// value from the command line, the file or the default; a setting without a default (an
/// optional one, unset) is written as a comment.
[[nodiscard]] std::string effective_config_yaml(const CLI::App& command);

/// What --config/--print-config ask of the innermost parsed subcommand of `app`: applies the
/// file and prints the configuration. Returns an exit code when the program should stop here
/// (printed, or a bad file), or -1 to run the command.
[[nodiscard]] int handle_config_options(CLI::App& app);

}  // namespace tessera::cli
