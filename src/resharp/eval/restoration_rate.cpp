#include "resharp/eval/restoration_rate.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "resharp/core/errors.h"
#include "resharp/mesh/uniform_grid.h"

namespace resharp::eval {
namespace {

using detail::Box3;
using detail::UniformGrid;

UniformGrid grid_over(std::span<const Vec3> points, double cell) {
    return UniformGrid(
        points.size(), [&](std::size_t i) { return Box3(points[i], points[i]); }, cell);
}

double nearest_distance(const UniformGrid& grid, std::span<const Vec3> points, const Vec3& p) {
    return grid.nearest(p, [&](Index j) { return (points[j] - p).norm(); }).second;
}

double rate(std::size_t restored, std::size_t total) {
    return total == 0 ? 1.0 : double(restored) / double(total);
}

}  // namespace

void check_output_extends_input(const Mesh& input, const Mesh& output) {
    if (output.vertex_count() < input.vertex_count()) {
        throw InvalidInput("the output has fewer vertices than the input");
    }
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        if (output.positions[v] != input.positions[v]) {
            std::ostringstream s;
            s << "output vertex " << v << " is not input vertex " << v
              << ": the output must start with the input's vertices, in order";
            throw InvalidInput(s.str());
        }
    }
}

RestorationScore score_restoration(const Mesh& input, const Mesh& output,
                                   std::span<const IdealPoint> ideal, const SurfaceSamples& exact,
                                   const RestorationOptions& options) {
    check_output_extends_input(input, output);
    if (exact.size() == 0) throw InvalidInput("the exact surface has no samples");
    if (!(options.pitch > 0 && options.tolerance > 0)) {
        throw InvalidInput("restoration score: pitch and tolerance must be positive");
    }
    const double h = options.pitch, tau = options.tolerance * h;
    const std::span<const Vec3> fresh(output.positions.data() + input.vertex_count(),
                                      output.vertex_count() - input.vertex_count());
    RestorationScore s;
    s.new_vertices = fresh.size();

    // Ideal points to new vertices (or to every output vertex): the rate.
    s.ideal_distance = nearest_distances(
        ideal, options.count_input_vertices ? std::span(output.positions) : fresh, 4.0 * h);
    std::vector<double> input_distance;
    if (options.count_input_vertices) input_distance = nearest_distances(ideal, input.positions, h);
    std::vector<Vec3> counted;  // ideal points off the boundary, for false insertions
    for (std::size_t i = 0; i < ideal.size(); ++i) {
        const IdealPoint& p = ideal[i];
        if (p.on_boundary) {
            s.ideal_distance[i] = std::numeric_limits<double>::quiet_NaN();
            continue;
        }
        counted.push_back(p.position);
        const bool restored = s.ideal_distance[i] <= tau;
        s.restored_by_input_vertices += !input_distance.empty() && input_distance[i] <= tau;
        if (p.kind == IdealKind::Edge) {
            ++s.ideal_edges;
            s.restored_edges += restored;
            s.beyond_chord += p.beyond_chord;
            s.restored_beyond_chord += p.beyond_chord && restored;
        } else {
            ++s.ideal_corners;
            s.restored_corners += restored;
        }
    }
    s.rate = rate(s.restored_edges + s.restored_corners, s.ideal_edges + s.ideal_corners);
    s.rate_edges = rate(s.restored_edges, s.ideal_edges);
    s.rate_corners = rate(s.restored_corners, s.ideal_corners);
    s.rate_within_reach = rate(s.restored_edges + s.restored_corners - s.restored_beyond_chord,
                               s.ideal_edges + s.ideal_corners - s.beyond_chord);

    // New vertices to ideal points and to the exact surface.
    const UniformGrid ideal_grid = grid_over(counted, h);
    const UniformGrid exact_grid = grid_over(exact.points, h);
    for (const Vec3& p : fresh) {
        if (!(nearest_distance(ideal_grid, counted, p) <= tau)) ++s.false_insertions;
        s.max_new_vertex_distance =
            std::max(s.max_new_vertex_distance, nearest_distance(exact_grid, exact.points, p));
    }
    return s;
}

}  // namespace resharp::eval
