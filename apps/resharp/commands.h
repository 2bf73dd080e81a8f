#pragma once
/// The subcommands of the `resharp` executable. Each add_* function registers one subcommand on
/// the app; its callback does the work and reports failure by throwing (main.cpp maps exceptions
/// to exit codes).

#include <CLI/CLI.hpp>

namespace resharp::cli {

/// Exit codes shared by every subcommand (listed in `resharp --help`).
enum ExitCode : int {
    kSuccess = 0,
    kUsageError = 1,     ///< bad command line (unknown flag, missing argument)
    kBadInput = 2,       ///< an input file is unreadable or malformed, or the mesh is refused
    kOutputFailed = 3,   ///< an output file could not be written
    kInternalError = 4,  ///< a bug or out of memory; no output file is left behind
};

// One add_*_command per subcommand, each defined in its own <name>_command.cpp.
void add_restore_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_evaluate_command(CLI::App& app);
/// Only in builds with the viewer (RESHARP_BUILD_VIEWER).
void add_view_command(CLI::App& app);

}  // namespace resharp::cli
