#include <gtest/gtest.h>

#include "resharp/mesh/geometry.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/segmentation/edge_segmentation.h"
#include "resharp/segmentation/feature_segmentation.h"
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
    const auto k = estimate_principal_curvatures(mesh, c.connectivity,
                                                 vertex_normals(mesh, c.connectivity));
    const EdgeSegmentation edges = segment_edges(mesh, c.connectivity, k, c.face_normals);
    c.features = segment_features(mesh, c.connectivity, c.face_normals, edges.is_edge);
    c.bands = classify_bands(mesh, c.connectivity, c.face_normals, edges.is_edge,
                             c.features.face_patch, c.features.vertex_patch);
    return c;
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

TEST(FeatureNormals, BandVerticesOfABoxGetTheirFacesExactNormal) {
    const test::SampledShape shape = test::sampled_box();
    const Classified c = classify(shape.mesh);
    const std::vector<Vec3> n = feature_normals(shape.mesh, c.connectivity, c.face_normals,
                                                c.features.face_patch, c.features.vertex_patch,
                                                c.bands)
                                    .normal;
    std::size_t checked = 0;
    for (Index f = 0; f < shape.mesh.face_count(); ++f) {
        if (c.bands.face_role[f] == BandRole::None) continue;
        for (Index v : shape.mesh.triangles[f]) {
            EXPECT_LT((n[v] - shape.exact_normals[v]).norm(), 1e-12) << "vertex " << v;
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
    const BandClassification paper =
        classify_bands(shape.mesh, c.connectivity, c.face_normals, no_edge_vertices,
                       c.features.face_patch, c.features.vertex_patch,
                       {.unconfirmed_border_angle_deg = 180.0});
    EXPECT_EQ(paper.crossing_edges, 0u);
}

}  // namespace
}  // namespace resharp
