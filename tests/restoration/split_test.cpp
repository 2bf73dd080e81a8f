#include "resharp/restoration/split.h"

#include <gtest/gtest.h>

#include "resharp/eval/self_intersections.h"
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
    bands.is_crossing.assign(3 * s.mesh.face_count(), 0);
    bands.face_role.assign(s.mesh.face_count(), BandRole::None);
    bands.face_role[0] = bands.face_role[1] = BandRole::Edge;
    for (Index h = 0; h < bands.is_crossing.size(); ++h) {
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
                                          {s.feature_normals, std::vector<float>(4, 0.0f)},
                                          s.feature_normals, points, report, source);
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
        const Vec3 n =
            triangle_normal(out.positions[t[0]], out.positions[t[1]], out.positions[t[2]]);
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
                                          {s.feature_normals, std::vector<float>(4, 0.0f)},
                                          s.feature_normals, points, report, source);
    EXPECT_EQ(report.refused_by_quality, 1u);
    EXPECT_EQ(out.vertex_count(), 4u);
    EXPECT_EQ(out.triangles, s.mesh.triangles);
}

Mesh split(const Strip& s, SharpPoints& points, SplitReport& report,
           const SplitOptions& options = {}) {
    std::vector<Index> source;
    const std::vector<float> exact(s.mesh.vertex_count(), 0.0f);
    return split_band_triangles(s.mesh, s.connectivity, s.face_normals, {s.feature_normals, exact},
                                s.feature_normals, points, report, source, options);
}

TEST(SplitGuard, RefusesAPieceTurnedAgainstTheFaceItReplaces) {
    // Off the ideal (0, 0, 0.75) towards -x, the point keeps piece (a0, a1, M) on the side of
    // the top's normal, as a wrong feature normal would, but folds it back over face 0 (the
    // paper's flip: M' projects outside the face it comes from). Without the guard it is kept.
    Strip s = make_strip();
    SharpPoints points = points_on_edge_a1_b0(s);
    points.points[0] = Vec3(-0.2225, 0.1, 0.75);
    const Vec3 piece =
        (s.mesh.positions[1] - s.mesh.positions[0]).cross(points.points[0] - s.mesh.positions[0]);
    ASSERT_GT(piece.dot(s.feature_normals[0]), 0.0);
    ASSERT_LT(piece.dot(s.face_normals[0]), 0.0);
    SplitReport report;
    const Mesh out = split(s, points, report);
    EXPECT_EQ(report.refused_by_guard, 1u);
    EXPECT_EQ(report.refused_by_quality, 0u);
    EXPECT_EQ(out.triangles, s.mesh.triangles);
}

/// The strip with a triangle hanging from b0 into the space between face 0 and the sharp edge,
/// where the pieces of the split go.
Strip strip_with_blocker() {
    Strip s = make_strip();
    const Vec3 a0 = s.mesh.positions[0], b0 = s.mesh.positions[2], m(0, 0, 0.75);
    const Vec3 inside = (a0 + 2.0 * m + b0) / 4.0;  // on piece (a0, M, b0)
    const Vec3 across = (m - a0).cross(b0 - a0).normalized();
    s.mesh.positions.push_back(inside + 0.1 * across);
    s.mesh.positions.push_back(inside - 0.03 * across);
    s.mesh.triangles.push_back({2, 4, 5});
    s.connectivity = build_connectivity(s.mesh);
    s.face_normals = face_normals(s.mesh);
    s.feature_normals.resize(6, Vec3::Zero());
    return s;
}

TEST(SplitGuard, RefusesAPointWhosePiecesWouldCutThroughANearbyFace) {
    const Strip plain = make_strip();
    SharpPoints unguarded = points_on_edge_a1_b0(plain);
    SplitReport plain_report;
    Mesh pieces = split(plain, unguarded, plain_report);
    ASSERT_EQ(plain_report.new_vertices, 1u);
    // The pieces the plain strip gets would cut through the blocker...
    const Strip s = strip_with_blocker();
    pieces.positions.insert(pieces.positions.end(), s.mesh.positions.begin() + 4,
                            s.mesh.positions.end());
    pieces.triangles.push_back({2, 5, 6});
    ASSERT_FALSE(eval::self_intersecting_pairs(pieces).empty());
    ASSERT_TRUE(eval::self_intersecting_pairs(s.mesh).empty());
    // ... so with the blocker there and the clearance check on, the point is refused and
    // nothing intersects; without the check (the default) it is kept.
    SharpPoints points = points_on_edge_a1_b0(s);
    SplitReport report;
    const Mesh out = split(s, points, report, {.check_clearance = true});
    EXPECT_EQ(report.refused_by_guard, 1u);
    EXPECT_EQ(report.new_vertices, 0u);
    EXPECT_TRUE(eval::self_intersecting_pairs(out).empty());
    SharpPoints unchecked_points = points_on_edge_a1_b0(s);
    SplitReport unchecked;
    split(s, unchecked_points, unchecked);
    EXPECT_EQ(unchecked.new_vertices, 1u);
}

}  // namespace
}  // namespace resharp
