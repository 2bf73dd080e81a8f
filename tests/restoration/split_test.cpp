#include "resharp/restoration/split.h"

#include <gtest/gtest.h>

#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

// A strip of two chamfer triangles across a convex right-angle edge along z: a0, a1 on the top
// face y = 0, b0, b1 on the side face x = 0.
struct Strip {
    Mesh mesh;
    Connectivity connectivity;
    std::vector<Vec3> face_normals;
    std::vector<Vec3> feature_normals;
};

Strip make_strip() {
    Strip s;
    s.mesh.positions = {{-0.3, 0, 0}, {-0.25, 0, 1}, {0, -0.2, 0.5}, {0, -0.3, 1.5}};
    s.mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    s.connectivity = build_connectivity(s.mesh);
    s.face_normals = face_normals(s.mesh);
    s.feature_normals = {{0, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 0, 0}};
    return s;
}

SharpPoints points_on_edge_a1_b0(const Strip& s) {
    BandClassification bands;
    bands.is_crossing.assign(6, 0);
    bands.face_role.assign(2, BandRole::Edge);
    for (Index h = 0; h < 6; ++h) {
        const Index u = tail_vertex(s.mesh, h), v = head_vertex(s.mesh, h);
        if ((u == 1 && v == 2) || (u == 2 && v == 1)) bands.is_crossing[h] = 1;
    }
    return place_sharp_points(s.mesh, s.connectivity, s.face_normals, bands, s.feature_normals);
}

TEST(Split, OneCrossingEdgeSplitsBothFacesAtTheIdealPoint) {
    const Strip s = make_strip();
    SharpPoints points = points_on_edge_a1_b0(s);
    ASSERT_EQ(points.edge_points, 1u);
    SplitReport report;
    std::vector<Index> source;
    const Mesh out = split_band_triangles(s.mesh, s.connectivity, s.face_normals,
                                          {s.feature_normals, std::vector<float>(4, 0.0f)}, s.feature_normals, points, report, source);
    EXPECT_EQ(source, (std::vector<Index>{0, 0, 1, 1}));
    EXPECT_EQ(report.refused_by_quality, 0u);
    EXPECT_EQ(report.new_vertices, 1u);
    EXPECT_EQ(report.split_faces, 2u);
    ASSERT_EQ(out.vertex_count(), 5u);
    ASSERT_EQ(out.face_count(), 4u);
    for (Index v = 0; v < 4; ++v) EXPECT_EQ(out.positions[v], s.mesh.positions[v]);
    EXPECT_TRUE(out.positions[4].isApprox(Vec3(0, 0, 0.75), 1e-15));
    // Orientation kept: every piece faces outward like the strip.
    for (std::size_t f = 0; f < out.face_count(); ++f) {
        const Triangle& t = out.triangles[f];
        const Vec3 n = triangle_normal(out.positions[t[0]], out.positions[t[1]], out.positions[t[2]]);
        EXPECT_GT(n.dot(Vec3(1, 1, 0)), 0.0) << "piece " << f;
    }
}

TEST(Split, DropsAPointWhoseSplitWouldTurnAPieceOver) {
    Strip s = make_strip();
    SharpPoints points = points_on_edge_a1_b0(s);
    points.points[0] = Vec3(-2.0, 3.0, 0.75);  // far off: pieces would flip
    SplitReport report;
    std::vector<Index> source;
    const Mesh out = split_band_triangles(s.mesh, s.connectivity, s.face_normals,
                                          {s.feature_normals, std::vector<float>(4, 0.0f)}, s.feature_normals, points, report, source);
    EXPECT_EQ(report.refused_by_quality, 1u);
    EXPECT_EQ(out.vertex_count(), 4u);
    EXPECT_EQ(out.triangles, s.mesh.triangles);
}

}  // namespace
}  // namespace resharp
