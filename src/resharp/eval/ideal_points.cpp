#include "resharp/eval/ideal_points.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "resharp/core/errors.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/uniform_grid.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp::eval {
namespace {

/// True when p, projected along the normal of face f, falls inside f (edges included).
bool lies_over_face(const Mesh& mesh, Index f, const Vec3& p) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.positions[t[0]];
    const Vec3& b = mesh.positions[t[1]];
    const Vec3& c = mesh.positions[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    if (n.isZero(0.0)) return false;
    // The signs of the projection's barycentric coordinates.
    return (c - b).cross(p - b).dot(n) >= 0.0 && (a - c).cross(p - c).dot(n) >= 0.0 &&
           (b - a).cross(p - a).dot(n) >= 0.0;
}

/// True when p lies over neither face of half-edge h's edge.
bool over_neither_face(const Mesh& mesh, const Connectivity& c, Index h, const Vec3& p) {
    return !lies_over_face(mesh, face_of(h), p) &&
           (c.twin[h] == kNoIndex || !lies_over_face(mesh, face_of(c.twin[h]), p));
}

/// See IdealPoint::beyond_chord; m is the ideal point of half-edge h, from u to v.
bool beyond_chord(const Mesh& mesh, const Connectivity& c, const Oracle& o, Index h, Index u,
                  Index v, const Vec3& m) {
    if (passes_flip_test(mesh.positions[u], o.normals[u], mesh.positions[v], o.normals[v])) {
        return false;
    }
    return over_neither_face(mesh, c, h, m);
}

}  // namespace

void check_oracle(const Oracle& oracle, const Mesh& mesh) {
    if (oracle.normals.size() != mesh.vertex_count() ||
        oracle.surfaces.size() != mesh.vertex_count() ||
        (!oracle.surface_points.empty() && oracle.surface_points.size() != mesh.vertex_count())) {
        throw InvalidInput("the oracle does not have one normal and surface per vertex");
    }
}

std::vector<IdealPoint> find_ideal_points(const Mesh& mesh, const Oracle& oracle,
                                          const IdealPointOptions& options) {
    check_oracle(oracle, mesh);
    const double min_cosine = std::cos(options.sharp_angle_deg * std::numbers::pi / 180.0);
    const Connectivity c = build_connectivity(mesh);
    std::vector<IdealPoint> points;
    for (Index h = 0; h < c.twin.size(); ++h) {
        if (c.twin[h] != kNoIndex && c.twin[h] < h) continue;  // each edge once
        const Index u = tail_vertex(mesh, h), v = head_vertex(mesh, h);
        if (!is_sharp_junction(oracle, u, v, min_cosine)) continue;
        const auto m =
            edge_point(mesh.positions[u], oracle.normals[u], mesh.positions[v], oracle.normals[v]);
        if (m) {
            points.push_back({*m,
                              IdealKind::Edge,
                              face_of(h),
                              {u, v, kNoIndex},
                              c.twin[h] == kNoIndex,
                              beyond_chord(mesh, c, oracle, h, u, v, *m)});
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
        const auto m =
            corner_point(mesh.positions[t[0]], oracle.normals[t[0]], mesh.positions[t[1]],
                         oracle.normals[t[1]], mesh.positions[t[2]], oracle.normals[t[2]]);
        if (m) points.push_back({*m, IdealKind::Corner, f, {t[0], t[1], t[2]}});
    }
    return points;
}

bool is_beyond_chord(const Mesh& mesh, const Connectivity& c, const Oracle& oracle,
                     const IdealPoint& point, const Vec3& p) {
    const Triangle& t = mesh.triangles[point.face];
    const Index u = point.vertices[0], v = point.vertices[1];
    for (Index k = 0; k < 3; ++k) {
        if (t[k] == u) return beyond_chord(mesh, c, oracle, 3 * point.face + k, u, v, p);
    }
    throw InvalidInput("an ideal edge point whose first vertex is not on its face");
}

std::vector<double> nearest_distances(std::span<const IdealPoint> ideal,
                                      std::span<const Vec3> candidates, double search_radius) {
    const detail::UniformGrid grid(
        candidates.size(),
        [&](std::size_t i) { return detail::Box3(candidates[i], candidates[i]); }, search_radius);
    std::vector<double> distance(ideal.size());
    for (std::size_t i = 0; i < ideal.size(); ++i) {
        const Vec3& p = ideal[i].position;
        const double d =
            grid.nearest(p, [&](Index j) { return (candidates[j] - p).norm(); }).second;
        distance[i] = d <= search_radius ? d : std::numeric_limits<double>::infinity();
    }
    return distance;
}

}  // namespace resharp::eval
