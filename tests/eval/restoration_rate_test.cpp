#include "resharp/eval/restoration_rate.h"

#include <gtest/gtest.h>

#include "resharp/core/errors.h"
#include "resharp/eval/miss_causes.h"

namespace resharp::eval {
namespace {

// Two triangles on the plane z = 0 sharing the edge (1, 2); h = 1, tau = 0.05.
Mesh two_triangles() {
    return {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}, {{0, 1, 2}, {1, 3, 2}}};
}

IdealPoint edge_point(const Vec3& p, Index u, Index v) {
    return {p, IdealKind::Edge, 0, {u, v, kNoIndex}, false};
}

SurfaceSamples plane_samples() {
    SurfaceSamples s;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
            s.points.push_back(Vec3(i * 0.25, j * 0.25, 0));
            s.normals.push_back(Vec3::UnitZ());
        }
    return s;
}

// Three ideal points: A has a new vertex 0.01 away (restored), B one 0.2 away (missed, and
// a false insertion), C none within 4 h. Corner D is restored exactly.
struct Scene {
    Mesh input = two_triangles();
    Mesh output;
    std::vector<IdealPoint> ideal;
    Scene() {
        ideal = {edge_point(Vec3(0.5, 0.5, 0), 1, 2),
                 edge_point(Vec3(2, 0, 0), 0, 1),
                 edge_point(Vec3(-5, 0, 0), 0, 2),
                 {Vec3(0, 3, 0), IdealKind::Corner, 1, {1, 3, 2}, false}};
        output = input;
        output.positions.push_back(Vec3(0.51, 0.5, 0));  // 4: restores A
        output.positions.push_back(Vec3(2, 0.2, 0.3));   // 5: 0.36 from B and from the plane
        output.positions.push_back(Vec3(0, 3, 0));       // 6: restores D
        output.triangles = {{0, 1, 4}, {0, 4, 2}, {1, 3, 4}, {4, 3, 2}};
    }
};

TEST(RestorationRate, CountsPointsWithinTau) {
    const Scene s;
    const RestorationScore r = score_restoration(s.input, s.output, s.ideal, plane_samples(),
                                                 {.pitch = 1.0, .tolerance = 0.05});
    EXPECT_EQ(r.ideal_edges, 3u);
    EXPECT_EQ(r.ideal_corners, 1u);
    EXPECT_EQ(r.restored_edges, 1u);
    EXPECT_EQ(r.restored_corners, 1u);
    EXPECT_DOUBLE_EQ(r.rate, 0.5);
    EXPECT_DOUBLE_EQ(r.rate_edges, 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(r.rate_corners, 1.0);
    EXPECT_EQ(r.new_vertices, 3u);
    EXPECT_EQ(r.false_insertions, 1u);
    EXPECT_NEAR(r.ideal_distance[0], 0.01, 1e-12);
    EXPECT_NEAR(r.ideal_distance[1], std::hypot(0.2, 0.3), 1e-12);
    EXPECT_TRUE(std::isinf(r.ideal_distance[2]));
    // The samples cover [0, 1]^2 only: the farthest new vertex is 6, 2 from sample (0, 1, 0).
    EXPECT_NEAR(r.max_new_vertex_distance, 2.0, 1e-12);
}

TEST(RestorationRate, BoundaryPointsAreLeftOut) {
    Scene s;
    s.ideal[2].on_boundary = true;
    const RestorationScore r =
        score_restoration(s.input, s.output, s.ideal, plane_samples(), {.pitch = 1.0});
    EXPECT_EQ(r.ideal_edges, 2u);
    EXPECT_TRUE(std::isnan(r.ideal_distance[2]));
}

// On the exact junction an input vertex may already lie on the sharp edge: with
// count_input_vertices it restores the point, and is counted as having done so.
TEST(RestorationRate, InputVerticesRestoreWhenCounted) {
    Scene s;
    s.ideal[2].position = Vec3(0.02, 1, 0);  // C: 0.02 from input vertex 2, no new vertex near
    const RestorationOptions plain{.pitch = 1.0, .tolerance = 0.05};
    RestorationOptions counted = plain;
    counted.count_input_vertices = true;
    const RestorationScore without =
        score_restoration(s.input, s.output, s.ideal, plane_samples(), plain);
    const RestorationScore with =
        score_restoration(s.input, s.output, s.ideal, plane_samples(), counted);
    EXPECT_EQ(without.restored_edges, 1u);
    EXPECT_EQ(without.restored_by_input_vertices, 0u);
    EXPECT_EQ(with.restored_edges, 2u);
    EXPECT_EQ(with.restored_by_input_vertices, 1u);
    EXPECT_NEAR(with.ideal_distance[2], 0.02, 1e-12);
    EXPECT_EQ(with.false_insertions, without.false_insertions);  // new vertices only
}

TEST(RestorationRate, RefusesAnOutputThatDoesNotStartWithTheInput) {
    Scene s;
    std::swap(s.output.positions[0], s.output.positions[1]);
    EXPECT_THROW(score_restoration(s.input, s.output, s.ideal, plane_samples()), InvalidInput);
    EXPECT_THROW(score_restoration(s.input, s.input, s.ideal, {}), InvalidInput);
}

TEST(MissCauses, ResolvesDetectionThenInsertion) {
    Scene s;
    const RestorationScore r =
        score_restoration(s.input, s.output, s.ideal, plane_samples(), {.pitch = 1.0});
    // Without labels: B (edge 0-1) has new vertex 4 joined to 0 and 1 -> placed far; C (edge
    // 0-2) likewise joined by 4 -> placed far. Make C's vertices share a patch instead.
    Segmentation seg;
    seg.is_edge_vertex = {1, 0, 0, 0};
    seg.vertex_patch = {0, 1, 0, 1};
    seg.face_role = {BandRole::Edge, BandRole::Edge};
    const MissCauses c = find_miss_causes(s.input, s.output, s.ideal, r.ideal_distance, 0.05, seg);
    EXPECT_EQ(c.edges[std::size_t(MissCause::PlacedFar)], 1u);  // B: patches 0 and 1
    EXPECT_EQ(c.edges[std::size_t(MissCause::SamePatch)], 1u);  // C: both on patch 0
    const MissCauses plain =
        find_miss_causes(s.input, s.input, s.ideal, std::vector<double>(4, 1.0), 0.05, {});
    EXPECT_EQ(plain.edges[std::size_t(MissCause::NotInserted)], 3u);
    EXPECT_EQ(plain.corners[std::size_t(MissCause::NotInserted)], 1u);
}

}  // namespace
}  // namespace resharp::eval
