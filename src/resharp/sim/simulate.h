#pragma once
/// Milling: a box stock minus the volume every move of a program sweeps (docs/design.md §4).

#include <cstddef>
#include <functional>
#include <map>
#include <vector>

#include "resharp/sim/gcode.h"
#include "resharp/sim/sweep.h"
#include "resharp/sim/tool.h"
#include "resharp/sim/tridexel.h"

namespace resharp::sim {

struct SimulationOptions {
    double pitch = 0.5;  ///< grid pitch h, mm
    /// Grid nodes sit at stock.min + (k + grid_phase) * pitch on every axis. The default keeps
    /// faces at round coordinates (a floor at z = 10, a wall at x = 25) off the grid planes, so
    /// every sharp edge becomes a chamfer band as in a production simulator; any phase gives a
    /// closed, manifold mesh.
    double grid_phase = 0.4142;
    double helix_tolerance = 1e-3;  ///< largest distance of a helical arc from its ramps, mm
    SweepOptions sweep;             ///< how swept volumes are intersected
};

struct SimulationStats {
    std::size_t moves = 0;          ///< moves in the program
    std::size_t cutting_moves = 0;  ///< moves with a tool loaded that reach the stock
    std::size_t swept_volumes = 0;  ///< volumes subtracted (helical arcs count once per ramp)
};

struct Simulation {
    DexelGrid grid;
    SimulationStats stats;
};

/// The volumes the moves of `path` sweep that reach `stock`, in program order: one per move with
/// a tool loaded (rapids included), one per ramp of a helical arc. `stats` (optional) receives
/// the counts.
/// \throws InvalidInput if a move uses a tool number the table lacks (naming the G-code line).
std::vector<SweptVolume> swept_volumes(const Box3& stock, const std::map<int, Tool>& tools,
                                       const ToolPath& path, const SimulationOptions& options = {},
                                       SimulationStats* stats = nullptr);

/// Mills `stock` (faces with surface ids 0..5: -x, +x, -y, +y, -z, +z) with the moves of `path`:
/// every move with a tool loaded, rapids included, removes the volume its tool sweeps (surface
/// ids tool_surface_id(move index, part)). `on_progress` (optional) receives the fraction done.
/// \throws InvalidInput if a move uses a tool number the table lacks ("SOURCE: line N: ..."),
/// or the pitch or stock is invalid or the grid would exceed 2^31 nodes.
Simulation simulate(const Box3& stock, const std::map<int, Tool>& tools, const ToolPath& path,
                    const SimulationOptions& options = {},
                    const std::function<void(double)>& on_progress = {});

}  // namespace resharp::sim
