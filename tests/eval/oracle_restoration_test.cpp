#include "resharp/eval/oracle_restoration.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "oracle_square.h"
#include "resharp/core/errors.h"
#include "resharp/eval/detection.h"
#include "support/grid_shapes.h"

namespace resharp::eval {
namespace {

using test::Square;

// Only the diagonal crosses: the sides (0, 2) and (1, 3) also join the two surfaces but have
// one face each, and boundaries are left as they are.
TEST(OracleRestoration, BandsAreManifoldSharpJunctions) {
    const Square s(Vec3(1, -1, 1), Vec3(-1, 1, 1));
    const BandClassification b = oracle_bands(s.mesh, s.oracle);
    EXPECT_EQ(b.crossing_edges, 1u);
    EXPECT_EQ(b.edge_triangles, 2u);
    EXPECT_EQ(b.is_crossing[1], 1u);  // half-edge 1 of face 0 runs from vertex 1 to 2
    EXPECT_EQ(b.is_crossing[2], 0u);  // 2 -> 0, a boundary
    Square gentle(Vec3(1, -1, 10), Vec3(-1, 1, 10));  // 16 degrees apart: no sharp junction
    EXPECT_EQ(oracle_bands(gentle.mesh, gentle.oracle).crossing_edges, 0u);
}

// Planes meeting beside the edge (beyond its chord): eq. 5.4 refuses the point even with the
// exact normals, so the mesh comes back as it was.
TEST(OracleRestoration, LeavesAPointBeyondTheChord) {
    const Square s(Vec3(2, 1, 1), Vec3(1, -2, 2));
    const OracleRestoration r = restore_from_oracle(s.mesh, s.oracle);
    EXPECT_EQ(r.refused_by_flip_test, 1u);
    EXPECT_EQ(r.mesh.positions, s.mesh.positions);
    EXPECT_EQ(r.mesh.triangles, s.mesh.triangles);
}

// On a simulated box (planes only, nothing beyond a chord) the oracle's bands are the detection
// ground truth, every crossing edge gets its ideal point exactly, and the eight corner triangles
// get the box's eight corners.
TEST(OracleRestoration, RestoresEveryEdgeAndCornerOfABox) {
    const test::SampledShape shape = test::sampled_box();
    const Oracle oracle{shape.exact_normals, shape.surface_ids};
    const OracleRestoration r = restore_from_oracle(shape.mesh, oracle);
    EXPECT_EQ(r.bands.face_role, true_band_roles(shape.mesh, oracle));
    const std::vector<IdealPoint> ideal = find_ideal_points(shape.mesh, oracle);
    const std::vector<Vec3> fresh(r.mesh.positions.begin() + shape.mesh.vertex_count(),
                                  r.mesh.positions.end());
    const std::vector<double> distance = nearest_distances(ideal, fresh, shape.pitch);
    std::size_t edges = 0, restored = 0;
    for (std::size_t i = 0; i < ideal.size(); ++i) {
        if (ideal[i].kind != IdealKind::Edge) continue;
        EXPECT_FALSE(ideal[i].beyond_chord);
        ++edges;
        restored += distance[i] < 1e-9;
    }
    EXPECT_GT(edges, 300u);  // about two per grid cell along 93 mm of edges
    EXPECT_EQ(restored, edges);
    std::size_t corners = 0;
    for (const Vec3& corner : shape.corners) {
        corners += std::any_of(fresh.begin(), fresh.end(),
                               [&](const Vec3& p) { return (p - corner).norm() < 1e-9; });
    }
    EXPECT_EQ(corners, 8u);
}

TEST(OracleRestoration, RefusesAnOracleOfAnotherMesh) {
    const Square s(Vec3(1, -1, 1), Vec3(-1, 1, 1));
    Oracle short_oracle = s.oracle;
    short_oracle.surfaces.pop_back();
    EXPECT_THROW(restore_from_oracle(s.mesh, short_oracle), InvalidInput);
    EXPECT_THROW(oracle_bands(s.mesh, short_oracle), InvalidInput);
}

// resharp's own detection with the exact normals in place of eq. 5.1's: the drilled plate's
// hole edges land on their ideal points (the ceiling of the placement step).
TEST(ExactNormalRestoration, PutsTheDrilledPlateHoleEdgesOnTheirIdealPoints) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    const Oracle oracle{shape.exact_normals, shape.surface_ids};
    const ExactNormalRestoration r = restore_with_exact_normals(shape.mesh, oracle);
    EXPECT_EQ(r.segmentation.face_role.size(), shape.mesh.face_count());
    const std::vector<IdealPoint> ideal = find_ideal_points(shape.mesh, oracle);
    const std::vector<Vec3> fresh(r.mesh.positions.begin() + shape.mesh.vertex_count(),
                                  r.mesh.positions.end());
    const std::vector<double> distance = nearest_distances(ideal, fresh, shape.pitch);
    std::size_t edges = 0, restored = 0;
    for (std::size_t i = 0; i < ideal.size(); ++i) {
        if (ideal[i].kind != IdealKind::Edge) continue;
        ++edges;
        restored += distance[i] <= 1e-9;
    }
    EXPECT_GE(restored, edges * 98 / 100);
    const Oracle short_oracle{std::vector<Vec3>(3, Vec3::UnitZ()), std::vector<std::int32_t>(3, 0)};
    EXPECT_THROW(restore_with_exact_normals(shape.mesh, short_oracle), InvalidInput);
}

}  // namespace
}  // namespace resharp::eval
