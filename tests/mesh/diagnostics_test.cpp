#include "resharp/mesh/diagnostics.h"

#include <gtest/gtest.h>

#include "support/simple_meshes.h"

namespace resharp {
namespace {

MeshDiagnostics diagnose_mesh(const Mesh& mesh) { return diagnose(mesh, build_connectivity(mesh)); }

TEST(Diagnostics, ClosedBoxIsClean) {
    const MeshDiagnostics d = diagnose_mesh(test::box_mesh());
    EXPECT_TRUE(d.is_clean_closed_manifold());
    EXPECT_EQ(d.components, 1u);
    EXPECT_EQ(d.isolated_vertices, 0u);
}

TEST(Diagnostics, BoxWithoutOneFaceHasFourBoundaryEdges) {
    Mesh mesh = test::box_mesh();
    mesh.triangles.erase(mesh.triangles.begin(), mesh.triangles.begin() + 2);
    const MeshDiagnostics d = diagnose_mesh(mesh);
    EXPECT_EQ(d.boundary_edges, 4u);
    EXPECT_FALSE(d.is_clean_closed_manifold());
}

TEST(Diagnostics, CountsDuplicateDegenerateAndFlippedFaces) {
    Mesh mesh = test::box_mesh();
    mesh.triangles.push_back(mesh.triangles[0]);  // duplicate: its edges become non-manifold
    mesh.triangles.push_back({0, 0, 1});          // degenerate
    mesh.positions.push_back({9, 9, 9});          // isolated
    const MeshDiagnostics d = diagnose_mesh(mesh);
    EXPECT_EQ(d.duplicate_faces, 1u);
    EXPECT_EQ(d.degenerate_faces, 1u);
    EXPECT_EQ(d.isolated_vertices, 1u);
    EXPECT_GE(d.nonmanifold_edges, 1u);

    Mesh flipped = test::box_mesh();
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    EXPECT_EQ(diagnose_mesh(flipped).inconsistent_edges, 3u);
}

TEST(Diagnostics, CountsComponentsAndNonManifoldVertices) {
    Mesh two = test::box_mesh();
    const Mesh other = test::box_mesh();
    for (const Vec3& p : other.positions) two.positions.push_back(p + Vec3(1, 1, 1));
    for (Triangle t : other.triangles) {
        for (Index& v : t) v += 8;
        two.triangles.push_back(t);
    }
    EXPECT_EQ(diagnose_mesh(two).components, 2u);

    // Glue the second box's corner onto the first box's corner 7: one vertex, two fans.
    for (Triangle& t : two.triangles) {
        for (Index& v : t)
            if (v == 8) v = 7;
    }
    const MeshDiagnostics glued = diagnose_mesh(two);
    EXPECT_EQ(glued.nonmanifold_vertices, 1u);
    EXPECT_EQ(glued.components, 1u);
}

}  // namespace
}  // namespace resharp
