#include "resharp/eval/ideal_points.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "resharp/mesh/connectivity.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp::eval {
namespace {

bool is_sharp_junction(const Oracle& o, Index u, Index v, double min_cosine) {
    return o.surfaces[u] != o.surfaces[v] && o.normals[u].dot(o.normals[v]) < min_cosine;
}

}  // namespace

std::vector<IdealPoint> find_ideal_points(const Mesh& mesh, const Oracle& oracle,
                                          const IdealPointOptions& options) {
    const double min_cosine = std::cos(options.sharp_angle_deg * std::numbers::pi / 180.0);
    const Connectivity c = build_connectivity(mesh);
    std::vector<IdealPoint> points;
    for (Index h = 0; h < c.twin.size(); ++h) {
        if (c.twin[h] != kNoIndex && c.twin[h] < h) continue;  // each edge once
        const Index u = tail_vertex(mesh, h), v = head_vertex(mesh, h);
        if (!is_sharp_junction(oracle, u, v, min_cosine)) continue;
        const auto m = edge_point(mesh.positions[u], oracle.normals[u], mesh.positions[v],
                                  oracle.normals[v]);
        if (m) {
            points.push_back({*m, IdealKind::Edge, face_of(h), {u, v, kNoIndex},
                              c.twin[h] == kNoIndex});
        }
    }
    for (Index f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        const bool three_surfaces = oracle.surfaces[t[0]] != oracle.surfaces[t[1]] &&
                                    oracle.surfaces[t[1]] != oracle.surfaces[t[2]] &&
                                    oracle.surfaces[t[0]] != oracle.surfaces[t[2]];
        if (!three_surfaces || !is_sharp_junction(oracle, t[0], t[1], min_cosine) ||
            !is_sharp_junction(oracle, t[1], t[2], min_cosine) ||
            !is_sharp_junction(oracle, t[2], t[0], min_cosine)) {
            continue;
        }
        const auto m = corner_point(mesh.positions[t[0]], oracle.normals[t[0]],
                                    mesh.positions[t[1]], oracle.normals[t[1]],
                                    mesh.positions[t[2]], oracle.normals[t[2]]);
        if (m) points.push_back({*m, IdealKind::Corner, f, {t[0], t[1], t[2]}});
    }
    return points;
}

std::vector<double> nearest_distances(std::span<const IdealPoint> ideal,
                                      std::span<const Vec3> candidates, double search_radius) {
    struct CellHash {
        std::size_t operator()(const Eigen::Vector3i& k) const {
            return (static_cast<std::size_t>(k.x()) * 73856093u) ^
                   (static_cast<std::size_t>(k.y()) * 19349663u) ^
                   (static_cast<std::size_t>(k.z()) * 83492791u);
        }
    };
    auto cell_of = [&](const Vec3& p) {
        return Eigen::Vector3i((p / search_radius).array().floor().cast<int>());
    };
    std::unordered_map<Eigen::Vector3i, std::vector<Index>, CellHash> grid;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        grid[cell_of(candidates[i])].push_back(static_cast<Index>(i));
    }
    std::vector<double> distance(ideal.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < ideal.size(); ++i) {
        const Eigen::Vector3i home = cell_of(ideal[i].position);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find(home + Eigen::Vector3i(dx, dy, dz));
                    if (it == grid.end()) continue;
                    for (Index j : it->second) {
                        const double d = (candidates[j] - ideal[i].position).norm();
                        if (d <= search_radius && d < distance[i]) distance[i] = d;
                    }
                }
    }
    return distance;
}

}  // namespace resharp::eval
