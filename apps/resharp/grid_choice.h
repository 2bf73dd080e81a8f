#pragma once
/// The grid pitch of `simulate` and `evaluate`, given in mm (--pitch) or as cells along the
/// longest side of the part (--cells), the same way in both so that evaluate sees the grid the
/// mesh was made on.

#include <CLI/CLI.hpp>

#include "resharp/sim/tridexel.h"

namespace resharp::cli {

/// Cells along the longest side of a CSG solid when neither flag is given.
inline constexpr double kDefaultSolidCells = 100.0;

struct GridChoice {
    double pitch = 0.0;  ///< --pitch in mm; 0: not given
    double cells = 0.0;  ///< --cells; 0: not given
};

/// Adds --pitch and --cells (mutually exclusive) to `command`; `fallback` says in the help what
/// applies when neither is given.
void add_grid_options(CLI::App& command, GridChoice& choice, const std::string& fallback);

/// The pitch in mm: --pitch, else --cells over `box`, else `fallback` if positive, else
/// kDefaultSolidCells over `box`. \throws InvalidInput for an empty box.
double resolve_pitch(const GridChoice& choice, const sim::Box3& box, double fallback);

}  // namespace resharp::cli
