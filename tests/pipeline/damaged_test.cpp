// Damaged meshes (docs/design.md §6): restore() finishes, counts each defect, leaves what it cannot
// treat as it was, and restores the sharp edges elsewhere.

#include <gtest/gtest.h>

#include <algorithm>
#include <span>

#include "resharp/eval/ideal_points.h"
#include "resharp/pipeline/restore.h"
#include "support/grid_shapes.h"
#include "support/invariants.h"

namespace resharp {
namespace {

/// Share of the box's ideal points farther than `keep_away` from `defect` that got a new vertex
/// within 1e-6 (exact on a box).
double restored_share_away_from(const test::SampledShape& shape, const Mesh& damaged,
                                const RestoreResult& r, const Vec3& defect, double keep_away) {
    std::vector<Vec3> normals = shape.exact_normals;
    std::vector<std::int32_t> surfaces = shape.surface_ids;
    normals.resize(damaged.vertex_count(), Vec3::UnitZ());
    surfaces.resize(damaged.vertex_count(), -1);
    Mesh clean = damaged;
    clean.triangles.resize(shape.mesh.face_count());  // ideal points of the undamaged faces
    const auto ideal = eval::find_ideal_points(clean, {normals, surfaces});
    const std::span<const Vec3> added(
        r.mesh.positions.begin() + static_cast<std::ptrdiff_t>(damaged.vertex_count()),
        r.mesh.positions.end());
    const auto miss = eval::nearest_distances(ideal, added, shape.pitch);
    std::size_t counted = 0, restored = 0;
    for (std::size_t i = 0; i < ideal.size(); ++i) {
        if (ideal[i].on_boundary || (ideal[i].position - defect).norm() < keep_away) continue;
        ++counted;
        restored += miss[i] <= 1e-6;
    }
    return counted == 0 ? 0.0 : static_cast<double>(restored) / static_cast<double>(counted);
}

Vec3 centroid(const Mesh& mesh, Index f) {
    const Triangle& t = mesh.triangles[f];
    return (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
}

/// A face of the top (+z, surface 5) whose vertices all lie on it, far from the edges.
Index middle_of_top(const test::SampledShape& shape) {
    Index best = kNoIndex;
    double best_distance = 1e9;
    const Vec3 target(5.29, 4.21, 6.07);
    for (Index f = 0; f < shape.mesh.face_count(); ++f) {
        const Triangle& t = shape.mesh.triangles[f];
        if (shape.surface_ids[t[0]] != 5 || shape.surface_ids[t[1]] != 5 ||
            shape.surface_ids[t[2]] != 5) {
            continue;
        }
        const double d = (centroid(shape.mesh, f) - target).norm();
        if (d < best_distance) {
            best_distance = d;
            best = f;
        }
    }
    return best;
}

TEST(DamagedMesh, NonManifoldFinIsCountedAndLeftAlone) {
    const test::SampledShape shape = test::sampled_box();
    Mesh mesh = shape.mesh;
    const Index f = middle_of_top(shape);
    const Triangle t = mesh.triangles[f];
    mesh.positions.push_back(centroid(mesh, f) + Vec3(0, 0, 1));
    mesh.triangles.push_back({t[0], t[1], static_cast<Index>(mesh.vertex_count() - 1)});
    const RestoreResult r = restore(mesh);
    EXPECT_EQ(r.report.input.nonmanifold_edges, 1u);
    test::expect_input_vertices_preserved(mesh, r.mesh);
    EXPECT_EQ(std::count(r.mesh.triangles.begin(), r.mesh.triangles.end(), mesh.triangles.back()),
              1);
    EXPECT_EQ(restored_share_away_from(shape, mesh, r, centroid(mesh, f), 2.0), 1.0);
}

TEST(DamagedMesh, DegenerateAndDuplicateFacesAreCountedAndKept) {
    const test::SampledShape shape = test::sampled_box();
    Mesh mesh = shape.mesh;
    const Index f = middle_of_top(shape);
    const Triangle t = mesh.triangles[f];
    mesh.triangles.push_back({t[0], t[0], t[1]});  // repeated vertex
    mesh.triangles.push_back(t);                   // duplicate
    const RestoreResult r = restore(mesh);
    EXPECT_EQ(r.report.input.degenerate_faces, 1u);
    EXPECT_EQ(r.report.input.duplicate_faces, 1u);
    test::expect_input_vertices_preserved(mesh, r.mesh);
    const auto& out = r.mesh.triangles;
    EXPECT_EQ(std::count(out.begin(), out.end(), Triangle{t[0], t[0], t[1]}), 1);
    EXPECT_EQ(restored_share_away_from(shape, mesh, r, centroid(mesh, f), 2.0), 1.0);
}

TEST(DamagedMesh, FlippedFaceIsCountedAndTheRestRestored) {
    const test::SampledShape shape = test::sampled_box();
    Mesh mesh = shape.mesh;
    const Index f = middle_of_top(shape);
    std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
    const RestoreResult r = restore(mesh);
    EXPECT_EQ(r.report.input.inconsistent_edges, 3u);
    EXPECT_EQ(restored_share_away_from(shape, mesh, r, centroid(mesh, f), 2.0), 1.0);
}

TEST(DamagedMesh, SeveralComponentsAndIsolatedVerticesAreAllRestored) {
    const test::SampledShape shape = test::sampled_box();
    Mesh two = shape.mesh;
    const Index offset = static_cast<Index>(two.vertex_count());
    for (const Vec3& p : shape.mesh.positions) two.positions.push_back(p + Vec3(20, 0, 0));
    for (Triangle t : shape.mesh.triangles) {
        for (Index& v : t) v += offset;
        two.triangles.push_back(t);
    }
    two.positions.push_back(Vec3(-5, -5, -5));  // isolated
    const RestoreResult r = restore(two);
    EXPECT_EQ(r.report.input.components, 2u);
    EXPECT_EQ(r.report.input.isolated_vertices, 1u);
    test::expect_input_vertices_preserved(two, r.mesh);
    const RestoreResult one = restore(shape.mesh);
    EXPECT_EQ(r.report.edge_points_inserted, 2 * one.report.edge_points_inserted);
    EXPECT_EQ(r.report.corner_points_inserted, 2 * one.report.corner_points_inserted);
}

}  // namespace
}  // namespace resharp
