#include "resharp/restoration/split.h"

#include <gtest/gtest.h>

#include "resharp/mesh/geometry.h"
#include "strip.h"

namespace resharp {
namespace {

TEST(Split, OneCrossingEdgeSplitsBothFacesAtTheIdealPoint) {
    const test::Strip s = test::make_strip();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    ASSERT_EQ(points.edge_points, 1u);
    const SplitMesh out = split_faces(s.mesh, points.points, points.slots);
    EXPECT_EQ(out.source_face, (std::vector<Index>{0, 0, 1, 1}));
    EXPECT_EQ(out.point_of_new_vertex, (std::vector<Index>{0}));
    EXPECT_EQ(out.split_faces, 2u);
    ASSERT_EQ(out.mesh.vertex_count(), 5u);
    ASSERT_EQ(out.mesh.face_count(), 4u);
    for (Index v = 0; v < 4; ++v) EXPECT_EQ(out.mesh.positions[v], s.mesh.positions[v]);
    EXPECT_TRUE(out.mesh.positions[4].isApprox(Vec3(0, 0, 0.75), 1e-15));
    // Orientation kept: every piece faces outward like the strip.
    for (const Triangle& t : out.mesh.triangles) {
        const auto& x = out.mesh.positions;
        EXPECT_GT(triangle_normal(x[t[0]], x[t[1]], x[t[2]]).dot(Vec3(1, 1, 0)), 0.0);
    }
}

TEST(Split, NoSlotLeftMeansTheInputComesBack) {
    const test::Strip s = test::make_strip();
    SharpPoints points = test::points_on_edge_a1_b0(s);
    points.slots = PointSlots(points.slots.face_count());
    const SplitMesh out = split_faces(s.mesh, points.points, points.slots);
    EXPECT_EQ(out.mesh.positions, s.mesh.positions);  // the unused point is not added
    EXPECT_EQ(out.mesh.triangles, s.mesh.triangles);
    EXPECT_EQ(out.split_faces, 0u);
}

TEST(Split, ACornerPointFansItsFace) {
    const test::Strip s = test::make_strip();
    SharpPoints points = test::points_on_edge_a1_b0(s);
    points.points.push_back(Vec3(-0.1, -0.05, 0.6));  // inside face 0, slightly off it
    points.slots.set_corner_point(0, 1);
    const SplitMesh out = split_faces(s.mesh, points.points, points.slots);
    // Face 0 has four boundary vertices (three corners and the edge point): a fan of four.
    EXPECT_EQ(std::count(out.source_face.begin(), out.source_face.end(), 0u), 4);
    EXPECT_EQ(out.point_of_new_vertex, (std::vector<Index>{0, 1}));
}

// Second-order placement puts a point beyond its edge's chord inside the face that holds it;
// the split fans that face around it and leaves the edge and the face across it whole.
TEST(Split, APointBeyondTheChordFansTheFaceThatHoldsIt) {
    const test::Strip s = test::make_strip_past_the_edge();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    ASSERT_EQ(points.face_points, 1u);
    ASSERT_EQ(points.slots.corner_point(0), 0u);
    const SplitMesh out = split_faces(s.mesh, points.points, points.slots);
    EXPECT_EQ(out.source_face, (std::vector<Index>{0, 0, 0, 1}));
    EXPECT_EQ(out.mesh.triangles[3], s.mesh.triangles[1]);
    ASSERT_EQ(out.mesh.vertex_count(), 5u);
    EXPECT_TRUE(out.mesh.positions[4].isApprox(Vec3(0, 0, 0.75), 1e-15));
    // Each piece keeps face 0's orientation.
    const auto& x = s.mesh.positions;
    const Triangle& f = s.mesh.triangles[0];
    const Vec3 face_normal = triangle_normal(x[f[0]], x[f[1]], x[f[2]]);
    for (Index i = 0; i < 3; ++i) {
        const Triangle& t = out.mesh.triangles[i];
        const auto& y = out.mesh.positions;
        EXPECT_GT(triangle_normal(y[t[0]], y[t[1]], y[t[2]]).dot(face_normal), 0.0);
    }
}

// Where a sharp edge ends at a corner of mixed convexity, a face's corner can lie past the line
// of the edge points beside it, and one of the two diagonals of the rest of the face turns a
// piece over. Here face (a, b, c) in z = 0 holds p on edge b-c and r on edge c-a; c is cut off
// as an ear and the quad (a, b, p, r) is left, with p inside triangle (a, b, r). Diagonal b-r
// gives the better-shaped worse triangle by area alone (0.64 against 0.16) but its piece
// (b, p, r) is turned over; the split takes a-p.
TEST(Split, TakesTheDiagonalThatTurnsNoPieceOver) {
    Mesh mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0)};
    mesh.triangles = {{0, 1, 2}};
    const std::vector<Vec3> points{Vec3(1, 0.3, 0), Vec3(0, 3, 0)};
    PointSlots slots(1);
    slots.set_edge_point(1, 0);  // edge b-c
    slots.set_edge_point(2, 1);  // edge c-a
    const SplitMesh out = split_faces(mesh, points, slots);
    ASSERT_EQ(out.mesh.face_count(), 3u);
    const auto& x = out.mesh.positions;
    for (const Triangle& t : out.mesh.triangles) {
        EXPECT_GT(triangle_normal(x[t[0]], x[t[1]], x[t[2]]).z(), 0.0);
    }
}

}  // namespace
}  // namespace resharp
