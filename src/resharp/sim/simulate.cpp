#include "resharp/sim/simulate.h"

#include <cmath>
#include <numbers>
#include <string>

#include "resharp/core/errors.h"
#include "resharp/sim/solids.h"

namespace resharp::sim {
namespace {

/// Replaces a helical arc by ramps through points of the helix, no farther than `tolerance`
/// from it in plan (the sagitta of each piece).
void add_helix_ramps(const Move& move, double tolerance, std::vector<ToolMotion>& motions) {
    const double ratio = std::max(-1.0, 1.0 - tolerance / move.radius);
    const double piece_angle = std::min(2.0 * std::acos(ratio), std::numbers::pi / 2);
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(move.sweep) / piece_angle)));
    const double a0 =
        std::atan2(move.start.y() - move.center.y(), move.start.x() - move.center.x());
    Vec3 previous = move.start;
    for (int i = 1; i <= pieces; ++i) {
        const double f = static_cast<double>(i) / pieces;
        const double angle = a0 + f * move.sweep;
        const Vec3 next = i == pieces ? move.end
                                      : Vec3(move.center.x() + move.radius * std::cos(angle),
                                             move.center.y() + move.radius * std::sin(angle),
                                             move.start.z() + f * (move.end.z() - move.start.z()));
        motions.push_back({.kind = ToolMotion::Kind::Line, .start = previous, .end = next});
        previous = next;
    }
}

/// The motions of one move: a line, a horizontal arc, or the ramps of a helix.
std::vector<ToolMotion> motions_of(const Move& move, double helix_tolerance) {
    std::vector<ToolMotion> motions;
    if (!move.is_arc()) {
        motions.push_back({.kind = ToolMotion::Kind::Line, .start = move.start, .end = move.end});
    } else if (move.start.z() == move.end.z()) {
        const double a0 =
            std::atan2(move.start.y() - move.center.y(), move.start.x() - move.center.x());
        motions.push_back({.kind = ToolMotion::Kind::Arc,
                           .start = move.start,
                           .end = move.end,
                           .center = move.center,
                           .radius = move.radius,
                           .start_angle = a0,
                           .sweep = move.sweep});
    } else {
        add_helix_ramps(move, helix_tolerance, motions);
    }
    return motions;
}

}  // namespace

std::vector<SweptVolume> swept_volumes(const Box3& stock, const std::map<int, Tool>& tools,
                                       const ToolPath& path, const SimulationOptions& options,
                                       SimulationStats* stats) {
    if (!(options.helix_tolerance > 0.0)) throw InvalidInput("helix tolerance must be positive");
    SimulationStats counts;
    counts.moves = path.moves.size();
    std::vector<SweptVolume> volumes;
    for (std::size_t i = 0; i < path.moves.size(); ++i) {
        const Move& move = path.moves[i];
        if (move.tool == 0) continue;
        const auto tool = tools.find(move.tool);
        if (tool == tools.end()) {
            throw InvalidInput(path.source + ": line " + std::to_string(move.line) +
                               ": uses tool T" + std::to_string(move.tool) +
                               ", which the tool table lacks");
        }
        bool cuts = false;
        for (const ToolMotion& motion : motions_of(move, options.helix_tolerance)) {
            SweptVolume volume(tool->second, motion, i, options.sweep);
            if (!volume.bounds().intersects(stock)) continue;
            volumes.push_back(std::move(volume));
            cuts = true;
        }
        counts.cutting_moves += cuts;
    }
    counts.swept_volumes = volumes.size();
    if (stats != nullptr) *stats = counts;
    return volumes;
}

Simulation simulate(const Box3& stock, const std::map<int, Tool>& tools, const ToolPath& path,
                    const SimulationOptions& options,
                    const std::function<void(double)>& on_progress) {
    const GridSpec spec = phased_grid(stock, options.pitch, options.grid_phase);

    Simulation result;
    const std::vector<SweptVolume> volumes =
        swept_volumes(stock, tools, path, options, &result.stats);

    result.grid = sample_solid(spec, axis_box(stock, 0));
    std::vector<const Solid*> order;
    order.reserve(volumes.size());
    for (const SweptVolume& v : volumes) order.push_back(&v);
    std::function<void(std::size_t, std::size_t)> tiles_done;
    if (on_progress) {
        tiles_done = [&](std::size_t done, std::size_t total) {
            on_progress(static_cast<double>(done) / static_cast<double>(total));
        };
    }
    subtract_in_order(result.grid, order, tiles_done);
    return result;
}

}  // namespace resharp::sim
