#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/segmentation/edge_segmentation.h"
#include "resharp/segmentation/feature_segmentation.h"
#include "resharp/surfaces/local_quadric.h"
#include "support/grid_shapes.h"

namespace resharp {
namespace {

struct Classified {
    Connectivity connectivity;
    std::vector<Vec3> face_normals;
    FeatureSegmentation features;
    BandClassification bands;
};

Classified classify(const Mesh& mesh) {
    Classified c{build_connectivity(mesh), face_normals(mesh), {}, {}};
    const auto k =
        estimate_principal_curvatures(mesh, c.connectivity, vertex_normals(mesh, c.connectivity));
    const EdgeSegmentation edges = segment_edges(mesh, c.connectivity, k, c.face_normals);
    c.features = segment_features(mesh, c.connectivity, c.face_normals, edges.is_edge);
    c.bands = classify_bands(mesh, c.connectivity, c.face_normals, edges.is_edge,
                             c.features.face_patch, c.features.vertex_patch);
    return c;
}

/// The feature normals of classify()'s bands, with the default options.
FeatureNormals fitted_normals(const Mesh& mesh, const Classified& c) {
    return feature_normals(mesh, c.connectivity, c.face_normals, c.features.face_patch,
                           c.features.vertex_patch, c.bands);
}

TEST(BandClassification, BoxCrossingEdgesAndCornersAreTheOraclesOwn) {
    const test::SampledShape shape = test::sampled_box();
    const Classified c = classify(shape.mesh);
    for (Index h = 0; h < c.bands.is_crossing.size(); ++h) {
        const Index u = tail_vertex(shape.mesh, h), v = head_vertex(shape.mesh, h);
        EXPECT_EQ(c.bands.is_crossing[h] != 0, shape.surface_ids[u] != shape.surface_ids[v])
            << "half-edge " << h;
    }
    EXPECT_EQ(c.bands.corner_triangles, 8u);
    for (Index f = 0; f < shape.mesh.face_count(); ++f) {
        const Triangle& t = shape.mesh.triangles[f];
        const int s0 = shape.surface_ids[t[0]], s1 = shape.surface_ids[t[1]],
                  s2 = shape.surface_ids[t[2]];
        const BandRole expected = (s0 != s1 && s1 != s2 && s0 != s2) ? BandRole::Corner
                                  : (s0 != s1 || s1 != s2)           ? BandRole::Edge
                                                                     : BandRole::None;
        EXPECT_EQ(c.bands.face_role[f], expected) << "face " << f;
    }
}

TEST(FeatureNormals, HoldNormalsCorrectionsAndFieldsOfTheVerticesGivenRoomAlone) {
    FeatureNormals n(10);
    n.add(7);
    n.normal_at(7) = Vec3(0, 0, 1);
    n.fit_correction_at(7) = 2.5f;
    EXPECT_EQ(n.normal(7), Vec3(0, 0, 1));
    EXPECT_EQ(n.fit_correction_deg(7), 2.5f);
    EXPECT_TRUE(n.normal(3).isZero(0.0));  // no room made: none
    EXPECT_EQ(n.fit_correction_deg(3), 0.0f);
    EXPECT_TRUE(n.field(7).n0.isZero(0.0));  // no fields kept
    n.keep_fields();
    n.add(2);
    n.add(7);  // room once: its entries stay
    EXPECT_EQ(n.normal(7), Vec3(0, 0, 1));
    n.field_at(7) = {Vec3(0, 0, 1), Eigen::Matrix3d::Identity()};
    EXPECT_EQ(n.field(7).gradient, Eigen::Matrix3d::Identity());
    EXPECT_TRUE(n.field(2).n0.isZero(0.0) && n.normal(2).isZero(0.0));
    n.drop_field(7);
    EXPECT_TRUE(n.field(7).n0.isZero(0.0) && n.field(7).gradient.isZero(0.0));
    EXPECT_EQ(n.normal(7), Vec3(0, 0, 1));  // the normal stays
    EXPECT_TRUE(FeatureNormals().field(0).n0.isZero(0.0));
}

TEST(FeatureNormals, CarryTheFieldAcrossABandUnlessAContinuationFieldIsSetApart) {
    FeatureNormals n(4);
    n.keep_fields();
    n.add(1);
    n.add(3);
    n.field_at(1) = {Vec3(0, 0, 1), Eigen::Matrix3d::Zero()};
    n.field_at(3) = {Vec3(0, 1, 0), Eigen::Matrix3d::Zero()};
    EXPECT_EQ(n.continuation_field(1).n0, Vec3(0, 0, 1));  // none kept apart: the field
    n.keep_continuation_fields();
    n.continuation_field_at(1) = {Vec3(1, 0, 0), Eigen::Matrix3d::Identity()};
    EXPECT_EQ(n.continuation_field(1).gradient, Eigen::Matrix3d::Identity());
    EXPECT_EQ(n.field(1).n0, Vec3(0, 0, 1));               // the field stays as it was
    EXPECT_EQ(n.continuation_field(3).n0, Vec3(0, 1, 0));  // none set at 3: its field
    n.drop_continuation_fields();
    EXPECT_EQ(n.continuation_field(1).n0, Vec3(0, 0, 1));
    n.add(2);  // room made after the drop holds no continuation entry
    EXPECT_TRUE(n.continuation_field(2).n0.isZero(0.0));
}

TEST(FeatureNormals, BandVerticesOfABoxGetTheirFacesExactNormal) {
    const test::SampledShape shape = test::sampled_box();
    const Classified c = classify(shape.mesh);
    const FeatureNormals n = fitted_normals(shape.mesh, c);
    std::size_t checked = 0;
    for (Index f = 0; f < shape.mesh.face_count(); ++f) {
        if (c.bands.face_role[f] == BandRole::None) continue;
        for (Index v : shape.mesh.triangles[f]) {
            EXPECT_LT((n.normal(v) - shape.exact_normals[v]).norm(), 1e-12) << "vertex " << v;
            ++checked;
        }
    }
    EXPECT_GT(checked, 300u);
}

}  // namespace
}  // namespace resharp

namespace resharp {
namespace {

TEST(BandClassification, SharpBordersCountWithoutEdgeVerticesUnlessThePaperRuleIsAsked) {
    const test::SampledShape shape = test::sampled_box();
    const Classified c = classify(shape.mesh);
    const std::vector<std::uint8_t> no_edge_vertices(shape.mesh.vertex_count(), 0);
    const BandClassification by_angle =
        classify_bands(shape.mesh, c.connectivity, c.face_normals, no_edge_vertices,
                       c.features.face_patch, c.features.vertex_patch);
    EXPECT_EQ(by_angle.crossing_edges, c.bands.crossing_edges);  // right angles: all confirmed
    const BandClassification paper = classify_bands(
        shape.mesh, c.connectivity, c.face_normals, no_edge_vertices, c.features.face_patch,
        c.features.vertex_patch, {.unconfirmed_border_angle_deg = 180.0});
    EXPECT_EQ(paper.crossing_edges, 0u);
}

TEST(BandClassification, SmoothBordersAreNoEdgesEvenWithEdgeVertices) {
    const test::SampledShape shape = test::sampled_box();
    const Classified c = classify(shape.mesh);
    // Split the top face's patch in two at x = 5, as merging that was held back would leave it,
    // and call every vertex an edge vertex.
    const Index top = static_cast<Index>(c.features.patch_count);
    std::vector<Index> face_patch = c.features.face_patch, vertex_patch = c.features.vertex_patch;
    auto on_top_left = [&](Index v) {
        return shape.surface_ids[v] == 5 && shape.mesh.positions[v].x() < 5.0;
    };
    for (Index v = 0; v < shape.mesh.vertex_count(); ++v) {
        if (on_top_left(v)) vertex_patch[v] = top;
    }
    for (Index f = 0; f < shape.mesh.face_count(); ++f) {
        const Triangle& t = shape.mesh.triangles[f];
        if (on_top_left(t[0]) && on_top_left(t[1]) && on_top_left(t[2])) face_patch[f] = top;
    }
    const std::vector<std::uint8_t> all_edge(shape.mesh.vertex_count(), 1);
    const BandClassification ours = classify_bands(shape.mesh, c.connectivity, c.face_normals,
                                                   all_edge, face_patch, vertex_patch);
    EXPECT_EQ(ours.crossing_edges, c.bands.crossing_edges);  // the box's edges, nothing more
    const BandClassification paper =
        classify_bands(shape.mesh, c.connectivity, c.face_normals, all_edge, face_patch,
                       vertex_patch, {.smooth_border_angle_deg = 0.0});
    EXPECT_GT(paper.crossing_edges, c.bands.crossing_edges + 10);  // the split across the top
}

}  // namespace
}  // namespace resharp

namespace resharp {
namespace {

/// A 7 x 7 vertex grid of pitch 0.5 folded by 20 degrees along the column x = 1.5: a crease that
/// region growing let into one patch. Every face and vertex lies on patch 0.
struct FoldedSheet {
    Mesh mesh;
    Index centre = kNoIndex;  ///< the vertex at (1, 1.5), one column before the fold
};

FoldedSheet folded_sheet() {
    const double pitch = 0.5, fold = 1.5, slope = std::tan(20.0 * std::numbers::pi / 180.0);
    FoldedSheet sheet;
    for (int j = 0; j < 7; ++j) {
        for (int i = 0; i < 7; ++i) {
            const double x = pitch * i;
            sheet.mesh.positions.emplace_back(x, pitch * j, std::max(0.0, x - fold) * slope);
        }
    }
    for (Index j = 0; j < 6; ++j) {
        for (Index i = 0; i < 6; ++i) {
            const Index a = 7 * j + i;
            sheet.mesh.triangles.push_back({a, a + 1, a + 8});
            sheet.mesh.triangles.push_back({a, a + 8, a + 7});
        }
    }
    sheet.centre = 7 * 3 + 2;
    return sheet;
}

// On the drilled plate's hole wall (radius 3.08 mm, normals pointing into the hole, towards its
// axis) the second-order shape of the fitted normal field bends towards the normal by 1 / r across
// the axis and not along it; on the flat faces it is zero.
TEST(FeatureNormals, CurvatureOfTheHoleWallIsOneOverItsRadius) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    const Classified c = classify(shape.mesh);
    const FeatureNormals fit = fitted_normals(shape.mesh, c);
    constexpr int kWall = 6;
    const double r = 3.08;
    std::size_t wall = 0, flat = 0, close = 0;
    for (Index v = 0; v < shape.mesh.vertex_count(); ++v) {
        if (fit.normal(v).isZero(0.0)) continue;
        const Eigen::Matrix3d frame = tangent_frame(fit.normal(v));
        const bool fitted = fit.field(v).n0 == fit.normal(v);  // the fit placed the normal
        const Eigen::Vector3d k =
            fitted ? quadric_from_normal_slope(shape.mesh.positions[v], fit.normal(v),
                                               fit.field(v).gradient)
                         .curvature
                   : Eigen::Vector3d::Zero();
        if (shape.surface_ids[v] != kWall) {
            flat += k.isZero(0.0);
            continue;
        }
        ++wall;
        // The curvature along the wall's horizontal tangent and along z.
        const Eigen::Vector2d across =
            (frame.leftCols<2>().transpose() * fit.normal(v).cross(Vec3::UnitZ())).normalized();
        const Eigen::Vector2d along = (frame.leftCols<2>().transpose() * Vec3::UnitZ());
        const Eigen::Matrix2d hessian{{k[0], k[1]}, {k[1], k[2]}};
        const double k_across = across.dot(hessian * across), k_along = along.dot(hessian * along);
        close += std::abs(k_across - 1.0 / r) < 0.15 / r && std::abs(k_along) < 0.1 / r;
    }
    // At h = 0.5 the wall's band vertices number about 100; a few near the top and bottom faces
    // have too few wall faces for a fit (curvature 0), the rest lie within 15 % of 1 / r.
    EXPECT_GT(wall, 80u);
    EXPECT_GT(close, 9 * wall / 10) << close << " of " << wall << " wall vertices";
    EXPECT_GT(flat, 300u);
}

TEST(FeatureNormals, FitLeavesOutFacesBeyondACreaseInsideThePatch) {
    const FoldedSheet sheet = folded_sheet();
    const Mesh& mesh = sheet.mesh;
    const Connectivity connectivity = build_connectivity(mesh);
    const std::vector<Index> face_patch(mesh.face_count(), 0), vertex_patch(mesh.vertex_count(), 0);
    BandClassification bands;
    bands.is_crossing.assign(3 * mesh.face_count(), 0);
    bands.face_role.assign(mesh.face_count(), BandRole::None);
    for (Index f : connectivity.faces_around(sheet.centre)) bands.face_role[f] = BandRole::Edge;
    auto normal_at_centre = [&](double max_residual_deg) {
        return feature_normals(mesh, connectivity, face_normals(mesh), face_patch, vertex_patch,
                               bands, {.max_fit_residual_deg = max_residual_deg})
            .normal(sheet.centre);
    };
    const Vec3 flat(0.0, 0.0, 1.0);
    EXPECT_LT((normal_at_centre(1.4) - flat).norm(), 1e-9);
    EXPECT_GT(angle_deg(normal_at_centre(180.0), flat), 1.0);  // every face kept: tilted
}

TEST(FeatureNormals, RejectsAnglesOutsideTheHalfTurn) {
    const FoldedSheet sheet = folded_sheet();
    const Connectivity connectivity = build_connectivity(sheet.mesh);
    const std::vector<Index> patch_of_faces(sheet.mesh.face_count(), 0);
    const std::vector<Index> patch_of_vertices(sheet.mesh.vertex_count(), 0);
    const BandClassification bands{std::vector<std::uint8_t>(3 * sheet.mesh.face_count()),
                                   std::vector<BandRole>(sheet.mesh.face_count()), 0, 0, 0};
    for (double bad : {-1.0, 181.0, std::numeric_limits<double>::quiet_NaN()}) {
        EXPECT_THROW(
            feature_normals(sheet.mesh, connectivity, face_normals(sheet.mesh), patch_of_faces,
                            patch_of_vertices, bands, {.max_fit_residual_deg = bad}),
            InvalidInput);
    }
}

// classify_bands() and drop_smooth_crossings() set the roles and counts of the faces whose edges
// they set or drop, one edge at a time: those must be what a classification of their crossing
// flags from scratch gives, whether few edges are dropped or most.
void expect_roles_and_counts_of_flags(const BandClassification& bands, double angle) {
    const BandClassification again = classify_faces(bands.is_crossing);
    EXPECT_EQ(bands.face_role, again.face_role) << angle;
    EXPECT_EQ(bands.crossing_edges, again.crossing_edges) << angle;
    EXPECT_EQ(bands.edge_triangles, again.edge_triangles) << angle;
    EXPECT_EQ(bands.corner_triangles, again.corner_triangles) << angle;
}

TEST(BandClassification, RolesAndCountsAreThoseOfTheCrossingFlags) {
    const test::SampledShape shape = test::sampled_drilled_plate();
    const Classified c = classify(shape.mesh);
    expect_roles_and_counts_of_flags(c.bands, 0.0);
    EXPECT_GT(c.bands.corner_triangles, 0u);
    const FeatureNormals fit = fitted_normals(shape.mesh, c);
    for (double angle : {25.0, 100.0, 179.0}) {
        ClassificationOptions options;
        options.smooth_continuation_angle_deg = angle;
        const BandClassification dropped =
            drop_smooth_crossings(shape.mesh, c.connectivity, c.bands, fit, options);
        expect_roles_and_counts_of_flags(dropped, angle);
        if (angle == 179.0) {
            EXPECT_LT(dropped.crossing_edges, c.bands.crossing_edges / 2);
        }
    }
}
}  // namespace
}  // namespace resharp
