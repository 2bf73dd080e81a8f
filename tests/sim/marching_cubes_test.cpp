#include "resharp/sim/marching_cubes.h"

#include <gtest/gtest.h>

#include "mesh_checks.h"
#include "resharp/sim/solids.h"

namespace resharp::sim {
namespace {

using test::expect_clean_closed_outward;

TEST(MeshDexels, SingleInsideNodeGivesAnOutwardOctahedron) {
    // A ball around one node, smaller than the pitch: six crossed edges, eight cells.
    const Sphere ball(Vec3(1, 1, 1), 0.3, 0);
    const OracleMesh m = mesh_dexels(sample_solid(grid_enclosing(ball.bounds(), 1.0), ball));
    EXPECT_EQ(m.mesh.vertex_count(), 6u);
    EXPECT_EQ(m.mesh.face_count(), 8u);
    expect_clean_closed_outward(m.mesh);
}

TEST(MeshDexels, SphereVerticesLieOnItWithRadialNormals) {
    const Vec3 centre(0.13, -0.21, 0.37);
    const Sphere ball(centre, 4.3, 7);
    const OracleMesh m = mesh_dexels(sample_solid(grid_enclosing(ball.bounds(), 0.5), ball));
    expect_clean_closed_outward(m.mesh);
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const Vec3 r = m.mesh.positions[v] - centre;
        EXPECT_NEAR(r.norm(), 4.3, 1e-12);
        EXPECT_NEAR((m.normals[v] - r / 4.3).norm(), 0.0, 1e-12);
        EXPECT_EQ(m.surface_ids[v], 7);
    }
    EXPECT_EQ(m.stats.clamped_vertices, 0u);
}

TEST(MeshDexels, FacesOnGridPlanesStayClosedWithVerticesOnThem) {
    // Every face of this box and of the pocket lies on a grid plane: the perturbation rule decides.
    const Box3 box(Vec3(0, 0, 0), Vec3(6, 5, 4));
    DexelGrid grid = sample_solid(grid_enclosing(box, 0.5), axis_box(box, 0));
    subtract(grid, axis_box(Box3(Vec3(1, 1, 2), Vec3(4, 3, 5)), 6));
    const OracleMesh m = mesh_dexels(grid);
    const MeshDiagnostics d = diagnose(m.mesh, build_connectivity(m.mesh));
    EXPECT_EQ(d.boundary_edges, 0u);
    EXPECT_EQ(d.nonmanifold_edges, 0u);
    EXPECT_EQ(d.inconsistent_edges, 0u);
    EXPECT_EQ(m.stats.clamped_vertices, 0u);
    EXPECT_GT(test::signed_volume(m.mesh), 0.0);
    const Box3 pocket(Vec3(1, 1, 2), Vec3(4, 3, 5));
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const int id = m.surface_ids[v];
        ASSERT_TRUE(id >= 0 && id < 12);
        const int axis = (id % 6) / 2;
        const bool is_max = id % 2 == 1;
        const Box3& owner = id < 6 ? box : pocket;
        const double plane = is_max ? owner.max()[axis] : owner.min()[axis];
        EXPECT_EQ(m.mesh.positions[v][axis], plane);
        // Box faces point out of it, pocket faces into the pocket.
        const double sign = (is_max ? 1.0 : -1.0) * (id < 6 ? 1.0 : -1.0);
        EXPECT_EQ(m.normals[v], Vec3(sign * Vec3::Unit(axis)));
    }
}

TEST(MeshDexels, WallThinnerThanThePitchLeavesNoHole) {
    // Two pockets leave a wall 0.31 mm thick across x; x-edges through it are crossed twice.
    const Box3 box(Vec3(0.37, 0.29, 0.41), Vec3(5.21, 4.13, 3.07));
    DexelGrid grid = sample_solid(grid_enclosing(box, 0.5), axis_box(box, 0));
    subtract(grid, axis_box(Box3(Vec3(1.1, 0.9, 1.0), Vec3(2.6, 3.5, 5)), 6));
    subtract(grid, axis_box(Box3(Vec3(2.91, 0.9, 1.0), Vec3(4.6, 3.5, 5)), 12));
    const OracleMesh m = mesh_dexels(grid);
    const MeshDiagnostics d = diagnose(m.mesh, build_connectivity(m.mesh));
    EXPECT_EQ(d.boundary_edges, 0u);
    EXPECT_EQ(d.nonmanifold_edges, 0u);
    EXPECT_EQ(d.inconsistent_edges, 0u);
    EXPECT_EQ(d.nonmanifold_vertices, 0u);
    EXPECT_GT(test::signed_volume(m.mesh), 0.0);
}

TEST(MeshDexels, SlabThinnerThanThePitchBetweenNodesLeavesNoHole) {
    // A plate 0.2 mm thick between two node layers: no node inside, so nothing is meshed, and
    // one that holds a node layer becomes a one-cell-thick closed sheet.
    const Box3 missed(Vec3(0.3, 0.3, 1.1), Vec3(4.2, 4.2, 1.3));
    EXPECT_EQ(mesh_dexels(sample_solid(grid_enclosing(missed, 0.5), axis_box(missed, 0)))
                  .mesh.face_count(),
              0u);
    const Box3 held(Vec3(0.3, 0.3, 0.9), Vec3(4.2, 4.2, 1.1));
    const OracleMesh m = mesh_dexels(sample_solid(grid_enclosing(held, 0.5), axis_box(held, 0)));
    const MeshDiagnostics d = diagnose(m.mesh, build_connectivity(m.mesh));
    EXPECT_EQ(d.boundary_edges + d.nonmanifold_edges + d.inconsistent_edges, 0u);
    EXPECT_GT(test::signed_volume(m.mesh), 0.0);
}

TEST(MeshDexels, IsDeterministicAndBothAmbiguityRulesGiveClosedMeshes) {
    // Two balls touching diagonally make faces with four crossings.
    const Box3 box(Vec3(-3, -3, -3), Vec3(6, 6, 6));
    DexelGrid grid = sample_solid(grid_enclosing(box, 0.5), axis_box(box, 0));
    for (int k = 0; k < 6; ++k)
        subtract(grid, Sphere(Vec3(0.7 * k, 0.55 * k, 0.3 * k), 1.2, 10 + k));
    const OracleMesh a = mesh_dexels(grid);
    const OracleMesh b = mesh_dexels(grid);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    EXPECT_EQ(a.mesh.positions, b.mesh.positions);
    for (AmbiguousFaceRule rule :
         {AmbiguousFaceRule::ShorterCut, AmbiguousFaceRule::SeparateInside}) {
        const OracleMesh m = mesh_dexels(grid, {.ambiguous_faces = rule});
        const MeshDiagnostics d = diagnose(m.mesh, build_connectivity(m.mesh));
        EXPECT_EQ(d.boundary_edges + d.nonmanifold_edges + d.inconsistent_edges, 0u);
        EXPECT_EQ(d.nonmanifold_vertices, 0u);
    }
}

}  // namespace
}  // namespace resharp::sim
