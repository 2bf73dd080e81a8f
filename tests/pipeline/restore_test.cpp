#include "resharp/pipeline/restore.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <span>

#include "resharp/core/errors.h"
#include "resharp/eval/ideal_points.h"
#include "support/grid_shapes.h"
#include "support/invariants.h"

namespace resharp {
namespace {

/// Restores a sampled shape and measures it against the exact answer.
struct Outcome {
    RestoreResult result;
    std::vector<eval::IdealPoint> ideal;
    std::vector<double> miss;  ///< per ideal point: distance to the nearest new vertex
    std::size_t restored_within(double tolerance, eval::IdealKind kind) const {
        std::size_t n = 0;
        for (std::size_t i = 0; i < ideal.size(); ++i)
            n += ideal[i].kind == kind && miss[i] <= tolerance;
        return n;
    }
    std::size_t count(eval::IdealKind kind) const {
        return static_cast<std::size_t>(std::count_if(
            ideal.begin(), ideal.end(), [&](const auto& p) { return p.kind == kind; }));
    }
};

Outcome restore_shape(const test::SampledShape& shape, const RestoreOptions& options = {}) {
    Outcome o;
    o.result = restore(shape.mesh, options);
    o.ideal = eval::find_ideal_points(shape.mesh, {shape.exact_normals, shape.surface_ids});
    const std::span<const Vec3> added(
        o.result.mesh.positions.begin() + static_cast<std::ptrdiff_t>(shape.mesh.vertex_count()),
        o.result.mesh.positions.end());
    o.miss = eval::nearest_distances(o.ideal, added, shape.pitch);
    return o;
}

void expect_invariants(const test::SampledShape& shape, const Outcome& o) {
    test::expect_input_vertices_preserved(shape.mesh, o.result.mesh);
    test::expect_closed_manifold(o.result.mesh);
    test::expect_no_flipped_triangles(shape.mesh, o.result.mesh, shape.exact_normals,
                                      o.result.source_face);
    test::expect_no_new_self_intersections(shape.mesh, o.result.mesh);
}

/// Largest distance from a new vertex to the nearest exact sharp edge or corner.
double worst_new_vertex_error(const test::SampledShape& shape, const Mesh& out) {
    double worst = 0.0;
    for (std::size_t v = shape.mesh.vertex_count(); v < out.vertex_count(); ++v) {
        double d = std::numeric_limits<double>::infinity();
        for (const auto& e : shape.edges) d = std::min(d, e.distance(out.positions[v]));
        worst = std::max(worst, d);
    }
    return worst;
}

/// Our choices and the paper's (paper_variant) must both restore the box exactly.
class RestoreBox : public ::testing::TestWithParam<bool> {};

TEST_P(RestoreBox, GetsEveryEdgeAndCornerBackExactly) {
    const test::SampledShape shape = test::sampled_box();
    const Outcome o = restore_shape(shape, GetParam() ? paper_variant({}) : RestoreOptions{});
    const RestoreReport& r = o.result.report;
    EXPECT_TRUE(r.input.is_clean_closed_manifold());
    EXPECT_EQ(r.feature_patches, 6u);
    EXPECT_EQ(o.count(eval::IdealKind::Corner), 8u);
    EXPECT_EQ(r.corner_triangles, 8u);
    EXPECT_EQ(r.crossing_edges, o.count(eval::IdealKind::Edge));
    EXPECT_EQ(o.restored_within(1e-6, eval::IdealKind::Edge), o.count(eval::IdealKind::Edge));
    EXPECT_EQ(o.restored_within(1e-6, eval::IdealKind::Corner), 8u);
    for (const Vec3& corner : shape.corners) {
        const auto& p = o.result.mesh.positions;
        const double nearest = std::transform_reduce(
            p.begin(), p.end(), std::numeric_limits<double>::infinity(),
            [](double a, double b) { return std::min(a, b); },
            [&](const Vec3& x) { return (x - corner).norm(); });
        EXPECT_LT(nearest, 1e-6) << "corner " << corner.transpose();
    }
    EXPECT_LT(worst_new_vertex_error(shape, o.result.mesh), 1e-6);
    EXPECT_EQ(r.edge_points_inserted + r.corner_points_inserted,
              o.result.mesh.vertex_count() - shape.mesh.vertex_count());
    expect_invariants(shape, o);
}

INSTANTIATE_TEST_SUITE_P(OursAndPapers, RestoreBox, ::testing::Bool(), [](const auto& param_info) {
    return param_info.param ? "Paper" : "Ours";
});

TEST(Restore, PaperVariantSetsThePapersChoicesAndKeepsTheRest) {
    RestoreOptions given;
    given.threads = 1;
    given.features.max_normal_angle_deg = 6.0;
    const RestoreOptions paper = paper_variant(given);
    EXPECT_EQ(paper.edges.feature, CurvatureFeature::Signed);
    EXPECT_EQ(paper.features.curved_region_faces, 0u);
    EXPECT_FALSE(paper.features.keep_sharp_borders_apart);
    EXPECT_EQ(paper.bands.unconfirmed_border_angle_deg, 180.0);
    EXPECT_EQ(paper.bands.smooth_border_angle_deg, 0.0);
    EXPECT_EQ(paper.normals.estimate, NormalEstimate::AngleWeighted);
    EXPECT_EQ(paper.threads, 1);
    EXPECT_EQ(paper.features.max_normal_angle_deg, 6.0);
}

TEST(Restore, LBlockRestoresItsConcaveEdge) {
    const test::SampledShape shape = test::sampled_l_block();
    const Outcome o = restore_shape(shape);
    EXPECT_EQ(o.result.report.feature_patches, 8u);
    // The concave edge: crossing edges between the step wall (6) and the step floor (10).
    std::size_t concave = 0, concave_restored = 0;
    for (std::size_t i = 0; i < o.ideal.size(); ++i) {
        if (o.ideal[i].kind != eval::IdealKind::Edge) continue;
        const auto a = shape.surface_ids[o.ideal[i].vertices[0]];
        const auto b = shape.surface_ids[o.ideal[i].vertices[1]];
        if (std::min(a, b) == 6 && std::max(a, b) == 10) {
            ++concave;
            concave_restored += o.miss[i] <= 1e-6;
        }
    }
    EXPECT_GT(concave, 20u);
    EXPECT_EQ(concave_restored, concave);
    const std::size_t edges = o.count(eval::IdealKind::Edge);
    EXPECT_GE(o.restored_within(1e-6, eval::IdealKind::Edge), edges * 97 / 100);
    EXPECT_LT(worst_new_vertex_error(shape, o.result.mesh), 1e-6);
    expect_invariants(shape, o);
}

TEST(Restore, DrilledPlateRestoresTheCurvedHoleEdges) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    const Outcome o = restore_shape(shape);
    EXPECT_EQ(o.result.report.feature_patches, 7u);
    const double tau = 0.05 * shape.pitch;  // docs/design.md §5
    const std::size_t edges = o.count(eval::IdealKind::Edge);
    EXPECT_GE(o.restored_within(tau, eval::IdealKind::Edge), edges * 98 / 100);
    EXPECT_EQ(o.restored_within(1e-6, eval::IdealKind::Corner), 8u);
    // Estimated normals on the cylinder are not exact, but new points stay on the edges.
    EXPECT_LT(worst_new_vertex_error(shape, o.result.mesh), tau);
    expect_invariants(shape, o);
}

TEST(Restore, RotatedBoxRestoresChamfersThatDoNotFollowTheGrid) {
    const test::SampledShape shape = test::sampled_rotated_box();
    const Outcome o = restore_shape(shape);
    EXPECT_EQ(o.result.report.feature_patches, 6u);
    const std::size_t edges = o.count(eval::IdealKind::Edge);
    EXPECT_GE(o.restored_within(1e-6, eval::IdealKind::Edge), edges * 90 / 100);
    EXPECT_LT(worst_new_vertex_error(shape, o.result.mesh), 1e-6);
    expect_invariants(shape, o);
}

TEST(Restore, SameBytesWhateverTheThreadCount) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    const RestoreResult one = restore(shape.mesh, {.threads = 1});
    // Two threads run work beside other work (the segmentations, the input's defect counts).
    for (const int threads : {0, 2}) {
        const RestoreResult all = restore(shape.mesh, {.threads = threads});
        EXPECT_EQ(one.mesh.triangles, all.mesh.triangles);
        ASSERT_EQ(one.mesh.vertex_count(), all.mesh.vertex_count());
        for (std::size_t v = 0; v < one.mesh.vertex_count(); ++v) {
            ASSERT_EQ(one.mesh.positions[v], all.mesh.positions[v]) << "vertex " << v;
        }
        EXPECT_EQ(all.report.input.components, 1u);
        EXPECT_TRUE(all.report.input.is_clean_closed_manifold());
        EXPECT_EQ(one.report.feature_patches, all.report.feature_patches);
    }
}

TEST(Restore, RestoresWhatItCanOnAnOpenBox) {
    test::SampledShape shape = test::sampled_box();
    // Cut away every face of the top (+z, surface 5) whose vertices all lie on it.
    std::erase_if(shape.mesh.triangles, [&](const Triangle& t) {
        return shape.surface_ids[t[0]] == 5 && shape.surface_ids[t[1]] == 5 &&
               shape.surface_ids[t[2]] == 5;
    });
    const Outcome o = restore_shape(shape);
    EXPECT_GT(o.result.report.input.boundary_edges, 0u);
    test::expect_input_vertices_preserved(shape.mesh, o.result.mesh);
    // The four vertical edges and the four bottom edges are still restored exactly, except
    // within two grid cells of the open rim (top at z = 6.07).
    std::size_t away_from_top = 0, restored = 0;
    for (std::size_t i = 0; i < o.ideal.size(); ++i) {
        const auto& p = o.ideal[i];
        if (p.on_boundary || p.position.z() > 6.07 - 2 * shape.pitch) continue;
        ++away_from_top;
        restored += o.miss[i] <= 1e-6;
    }
    EXPECT_GT(away_from_top, 100u);
    EXPECT_EQ(restored, away_from_top);
}

TEST(Restore, RejectsEmptyAndNonFiniteMeshes) {
    EXPECT_THROW(restore(Mesh{}), InvalidInput);
    Mesh bad = test::sampled_box().mesh;
    bad.positions[3].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(restore(bad), InvalidInput);
    Mesh out_of_range = test::sampled_box().mesh;
    out_of_range.triangles[0][1] = static_cast<Index>(out_of_range.vertex_count());
    EXPECT_THROW(restore(out_of_range), InvalidInput);
    EXPECT_THROW(restore(test::sampled_box().mesh, {.threads = -1}), InvalidInput);
    RestoreOptions bad_angle;
    bad_angle.features.max_normal_angle_deg = 0.0;
    EXPECT_THROW(restore(test::sampled_box().mesh, bad_angle), InvalidInput);
}

}  // namespace
}  // namespace resharp
