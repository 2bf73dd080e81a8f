#include "support/invariants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "resharp/eval/self_intersections.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"
#include "support/harm_criteria.h"

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

void expect_no_harm(const Mesh& input, const RestoreResult& r, const RestoreOptions& options) {
    EXPECT_LE(r.report.harm_rounds, static_cast<std::size_t>(options.max_harm_rounds));
    const HarmFound h = find_harm(input, r.mesh, r.source_face, criteria_for(r.report));
    EXPECT_EQ(h.moved_input_vertices, 0u);
    EXPECT_EQ(h.bad_source_faces, 0u);
    EXPECT_EQ(h.lost_faces, 0u);
    EXPECT_EQ(h.turned_faces, 0u);
    EXPECT_EQ(h.added_boundary_edges, 0u);
    EXPECT_EQ(h.added_nonmanifold_edges, 0u);
    EXPECT_EQ(h.added_inconsistent_edges, 0u);
    EXPECT_EQ(h.new_self_intersections, 0u);
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

}  // namespace resharp::test
