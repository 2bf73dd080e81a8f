#include "support/invariants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "resharp/eval/self_intersections.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"

namespace resharp::test {

void expect_input_vertices_preserved(const Mesh& input, const Mesh& output) {
    ASSERT_GE(output.vertex_count(), input.vertex_count());
    std::size_t moved = 0;
    for (std::size_t v = 0; v < input.vertex_count(); ++v) {
        if (output.positions[v] != input.positions[v]) {
            if (++moved <= 5) ADD_FAILURE() << "input vertex " << v << " moved";
        }
    }
    EXPECT_EQ(moved, 0u);
}

void expect_closed_manifold(const Mesh& mesh) {
    const MeshDiagnostics d = diagnose(mesh, build_connectivity(mesh));
    EXPECT_EQ(d.boundary_edges, 0u);
    EXPECT_EQ(d.nonmanifold_edges, 0u);
    EXPECT_EQ(d.inconsistent_edges, 0u);
    EXPECT_EQ(d.nonmanifold_vertices, 0u);
    EXPECT_EQ(d.degenerate_faces, 0u);
    EXPECT_EQ(d.duplicate_faces, 0u);
}

void expect_no_flipped_triangles(const Mesh& input, const Mesh& output,
                                 const std::vector<Vec3>& exact_normals,
                                 const std::vector<Index>& source_face) {
    ASSERT_EQ(source_face.size(), output.face_count());
    const std::vector<Vec3> before = face_normals(input);
    const std::vector<Vec3> after = face_normals(output);
    std::size_t flipped = 0;
    for (std::size_t f = 0; f < output.face_count(); ++f) {
        if (output.triangles[f] == input.triangles[source_face[f]]) continue;  // not cut
        bool is_flipped = false, has_input_vertex = false;
        for (Index v : output.triangles[f]) {
            if (v >= input.vertex_count()) continue;
            has_input_vertex = true;
            is_flipped |= after[f].dot(exact_normals[v]) <= 0.0;
        }
        if (!has_input_vertex) is_flipped = after[f].dot(before[source_face[f]]) <= 0.0;
        if (is_flipped && ++flipped <= 5) ADD_FAILURE() << "output face " << f << " is flipped";
    }
    EXPECT_EQ(flipped, 0u);
}

void expect_no_new_self_intersections(const Mesh& input, const Mesh& output) {
    const std::size_t before = eval::self_intersecting_pairs(input).size();
    EXPECT_LE(eval::self_intersecting_pairs(output).size(), before);
}

std::size_t turned_against_nearest(const Mesh& input, const RestoreResult& r) {
    const std::vector<Vec3> in = face_normals(input);
    std::vector<Vec3> centre(input.face_count());
    std::vector<double> radius(input.face_count());
    for (std::size_t g = 0; g < input.face_count(); ++g) {
        const Triangle& t = input.triangles[g];
        centre[g] = (input.positions[t[0]] + input.positions[t[1]] + input.positions[t[2]]) / 3.0;
        for (Index v : t) radius[g] = std::max(radius[g], (input.positions[v] - centre[g]).norm());
    }
    auto turned_at = [&](const Vec3& q, const Vec3& n) {
        double nearest = std::numeric_limits<double>::infinity();
        bool agrees = false;
        for (std::size_t g = 0; g < input.face_count(); ++g) {
            const double reach = std::max(0.0, (q - centre[g]).norm() - radius[g]);
            if (reach * reach > 1.01 * nearest + 1e-12) continue;  // cannot be among the nearest
            const Triangle& t = input.triangles[g];
            const double d = squared_distance_to_triangle(
                q, input.positions[t[0]], input.positions[t[1]], input.positions[t[2]]);
            // Ties within rounding: a vertex lies on every face around it, at a distance that
            // rounding may make 1e-17 instead of 0.
            constexpr double kTie = 1e-18;  // mm^2
            if (d < nearest - kTie) agrees = false;
            if (d <= nearest + kTie) agrees = agrees || in[g].dot(n) >= -1e-6;
            nearest = std::min(nearest, d);
        }
        return !agrees;
    };
    std::size_t turned = 0;
    for (std::size_t o = 0; o < r.mesh.face_count(); ++o) {
        const Triangle& t = r.mesh.triangles[o];
        if (t == input.triangles[r.source_face[o]]) continue;
        const auto& x = r.mesh.positions;
        const Vec3 n = triangle_normal(x[t[0]], x[t[1]], x[t[2]]);
        bool is_turned = n.isZero(0.0) || turned_at((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0, n);
        for (Index v : t) is_turned = is_turned || turned_at(x[v], n);
        turned += is_turned;
    }
    return turned;
}

void expect_no_harm(const Mesh& input, const RestoreResult& r, const RestoreOptions& options) {
    expect_input_vertices_preserved(input, r.mesh);
    const MeshDiagnostics before = diagnose(input, build_connectivity(input));
    const MeshDiagnostics after = diagnose(r.mesh, build_connectivity(r.mesh));
    EXPECT_LE(after.boundary_edges, before.boundary_edges);
    EXPECT_LE(after.nonmanifold_edges, before.nonmanifold_edges);
    EXPECT_LE(after.inconsistent_edges, before.inconsistent_edges);
    EXPECT_EQ(turned_against_nearest(input, r), 0u);
    expect_no_new_self_intersections(input, r.mesh);
    EXPECT_LE(r.report.harm_rounds, static_cast<std::size_t>(options.max_harm_rounds));
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

}  // namespace resharp::test
