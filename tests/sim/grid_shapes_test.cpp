#include "support/grid_shapes.h"

#include <gtest/gtest.h>

#include "mesh_checks.h"

namespace resharp::test {
namespace {

struct NamedShape {
    const char* name;
    SampledShape (*make)(double);
};

class GridShapeTest : public ::testing::TestWithParam<NamedShape> {};

TEST_P(GridShapeTest, IsClosedManifoldOutwardWithoutDegenerateFaces) {
    const SampledShape s = GetParam().make(0.5);
    expect_clean_closed_outward(s.mesh);
    EXPECT_EQ(s.stats.clamped_vertices, 0u);
    EXPECT_EQ(s.exact_normals.size(), s.mesh.vertex_count());
    EXPECT_EQ(s.surface_ids.size(), s.mesh.vertex_count());
}

TEST_P(GridShapeTest, EveryVertexLiesOnItsExactSurfaceWithItsExactNormal) {
    const SampledShape s = GetParam().make(0.5);
    const double tolerance = 1e-9 * s.scale;
    for (std::size_t v = 0; v < s.mesh.vertex_count(); ++v) {
        const Vec3& p = s.mesh.positions[v];
        ASSERT_TRUE(s.surfaces.count(s.surface_ids[v])) << "vertex " << v;
        const ExactSurface& surface = s.surfaces.at(s.surface_ids[v]);
        EXPECT_LE(s.distance_to_surface(p), tolerance) << "vertex " << v;
        EXPECT_LE(surface.distance(p), tolerance) << "vertex " << v;
        EXPECT_LE((s.exact_normals[v] - surface.normal_at(p)).norm(), 1e-9) << "vertex " << v;
    }
}

TEST_P(GridShapeTest, ChamfersCrossEveryEdgeAndNoVertexSitsOnOne) {
    const SampledShape s = GetParam().make(0.5);
    for (const ExactEdge& e : s.edges) {
        double nearest = 1e300;
        for (const Vec3& p : s.mesh.positions) nearest = std::min(nearest, e.distance(p));
        EXPECT_GT(nearest, 1e-9);           // the edge is lost to a chamfer...
        EXPECT_LT(nearest, 1.5 * s.pitch);  // ...but sampled right next to it
    }
}

TEST_P(GridShapeTest, FinerPitchStaysClean) {
    const SampledShape s = GetParam().make(0.27);
    expect_clean_closed_outward(s.mesh);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, GridShapeTest,
    ::testing::Values(NamedShape{"box", sampled_box}, NamedShape{"l_block", sampled_l_block},
                      NamedShape{"drilled_plate",
                                 [](double h) { return sampled_drilled_plate(h); }},
                      NamedShape{"rotated_box", sampled_rotated_box}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(GridShapes, DistanceHelpersAreExactAtKnownPoints) {
    const SampledShape plate = sampled_drilled_plate();
    EXPECT_NEAR(plate.distance_to_surface(Vec3(7.23, 6.17, 2.0)), 3.08, 1e-12);  // on the axis
    EXPECT_NEAR(plate.distance_to_surface(Vec3(7.23 + 3.08, 6.17, 5.07)), 1.0, 1e-12);  // over rim
    const SampledShape l = sampled_l_block();
    EXPECT_NEAR(l.distance_to_surface(Vec3(7.33, 4.0, 5.19)), 1.0, 1e-12);  // in the notch
    EXPECT_NEAR(l.distance_to_surface(Vec3(5.33, 4.0, 3.19)), std::sqrt(2.0),
                1e-12);  // by the valley
    const SampledShape box = sampled_rotated_box();
    EXPECT_NEAR(box.distance_to_surface(box.corners[0]), 0.0, 1e-12);
    EXPECT_EQ(box.edges.size(), 12u);
    EXPECT_EQ(l.edges.size(), 18u);
    EXPECT_EQ(l.corners.size(), 12u);
}

}  // namespace
}  // namespace resharp::test
