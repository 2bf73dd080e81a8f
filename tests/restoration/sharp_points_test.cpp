#include "resharp/restoration/sharp_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "resharp/restoration/pieces.h"
#include "strip.h"

namespace resharp {
namespace {

// Section through a convex right-angle edge along z at the origin: top face y = 0 (x < 0),
// side face x = 0 (y < 0).
const Vec3 kTop(0, 1, 0);
const Vec3 kSide(1, 0, 0);

TEST(PointSlots, KeepSlotsOnlyForFacesGivenAPointAndCompareByFace) {
    PointSlots a(1000);
    a.set_corner_point(999, kNoIndex);  // emptying a face without slots makes none
    EXPECT_EQ(a.faces_with_slots(), 0u);
    a.set_edge_point(3 * 7 + 2, 4);
    a.set_edge_point(3 * 8, 4);
    a.set_corner_point(500, 9);
    EXPECT_EQ(a.faces_with_slots(), 3u);
    EXPECT_EQ(a.edge_point(23), 4u);
    EXPECT_EQ(a.edge_point(22), kNoIndex);
    EXPECT_EQ(a.slot(500, 3), 9u);
    EXPECT_TRUE(a.has_points(7) && a.has_points(8) && a.has_points(500));
    EXPECT_FALSE(a.has_points(9));
    std::vector<Index> seen;
    a.for_each_point(7, [&](Index p) { seen.push_back(p); });
    EXPECT_EQ(seen, (std::vector<Index>{4}));
    // The same points given in another order: equal, though their rows lie elsewhere.
    PointSlots b(1000);
    b.set_corner_point(500, 9);
    b.set_edge_point(3 * 8, 4);
    b.set_edge_point(3 * 7 + 2, 4);
    EXPECT_TRUE(a == b);
    EXPECT_TRUE(a.same_at(500, b, 500));
    b.set_corner_point(500, kNoIndex);  // emptied, not gone: still unequal to a
    EXPECT_FALSE(a == b);
    EXPECT_FALSE(a.has_points(500) == b.has_points(500));
    a.empty_slots_of([](Index p) { return p == 9; });
    EXPECT_TRUE(a == b);
    EXPECT_FALSE(a == PointSlots(999));
}

TEST(EdgePoint, LandsOnTheIdealEdgeOfAConvexRightAngle) {
    const Vec3 a(-0.3, 0.0, 0.7);
    const Vec3 b(0.0, -0.2, 0.9);
    const auto m = edge_point(a, kTop, b, kSide);
    ASSERT_TRUE(m.has_value());
    EXPECT_NEAR(m->x(), 0.0, 1e-15);
    EXPECT_NEAR(m->y(), 0.0, 1e-15);
    EXPECT_NEAR(m->z(), 0.8, 1e-15);  // the mid-plane of eq. 5.2
    EXPECT_TRUE(passes_flip_test(a, kTop, b, kSide));
    EXPECT_TRUE(passes_flip_test(b, kSide, a, kTop));  // symmetric in its two ends
}

TEST(EdgePoint, ConcaveEdgePassesTheFlipTestToo) {
    // L-block inner edge: floor y = 0 (x > 0), wall x = 0 (y > 0).
    const Vec3 a(0.3, 0.0, 0.0);
    const Vec3 b(0.0, 0.2, 0.0);
    const auto m = edge_point(a, kTop, b, kSide);
    ASSERT_TRUE(m.has_value());
    EXPECT_LT(m->norm(), 1e-15);
    EXPECT_TRUE(passes_flip_test(a, kTop, b, kSide));
}

TEST(EdgePoint, FlipTestRefusesAPointOutsideTheBand) {
    // a lies on the top plane but beyond the edge: the traces meet behind a, not between.
    const Vec3 a(0.3, 0.0, 0.0);
    const Vec3 b(0.0, -0.2, 0.0);
    EXPECT_FALSE(passes_flip_test(a, kTop, b, kSide));
}

TEST(EdgePoint, FlipTestRefusesAPointAtAnEndAtEveryScale) {
    // The traces meet within rounding of a (1e-14 of the band's width away): eq. 5.4's sign is
    // then rounding, so the point is refused at any scale; 1e-6 of the width is a real band.
    for (double s : {1e-3, 1.0, 25.4, 1e3}) {
        SCOPED_TRACE(s);
        const Vec3 b = s * Vec3(0.0, -0.2, 0.0);
        EXPECT_FALSE(passes_flip_test(s * Vec3(-2e-15, 0.0, 0.0), kTop, b, kSide));
        EXPECT_TRUE(passes_flip_test(s * Vec3(-2e-7, 0.0, 0.0), kTop, b, kSide));
    }
}

TEST(EdgePoint, ParallelNormalsGiveNoPoint) {
    const Vec3 a(0, 0, 0), b(1, 0, 0);
    EXPECT_FALSE(edge_point(a, kTop, b, kTop).has_value());
    EXPECT_FALSE(passes_flip_test(a, kTop, b, kTop));
}

TEST(EdgePoint, ObliqueDihedralAngle) {
    // Planes through the z-axis with normals 40 degrees apart.
    const double t = 40.0 * M_PI / 180.0;
    const Vec3 n1(0, 1, 0), n2(std::sin(t), std::cos(t), 0);
    const Vec3 a(-0.4, 0.0, 0.0);                               // on plane 1
    const Vec3 b = 0.3 * Vec3(std::cos(t), -std::sin(t), 0.0);  // on plane 2
    const auto m = edge_point(a, n1, b, n2);
    ASSERT_TRUE(m.has_value());
    EXPECT_LT(m->norm(), 1e-14);
    EXPECT_TRUE(passes_flip_test(a, n1, b, n2));
}

TEST(CornerPoint, MeetsThreePlanes) {
    const auto m = corner_point(Vec3(0.9, 2, 0.5), Vec3(0, 1, 0), Vec3(1, 0.3, 0.1), Vec3(1, 0, 0),
                                Vec3(0.2, 0.1, 3), Vec3(0, 0, 1));
    ASSERT_TRUE(m.has_value());
    EXPECT_TRUE(m->isApprox(Vec3(1, 2, 3), 1e-15));
    EXPECT_FALSE(corner_point(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(1, 0, 0),
                              Vec3(2, 0, 0), Vec3(1, 0, 0))
                     .has_value());
}

// a1 lies past the sharp edge: eq. 5.4 fails for a1-b0, and eq. 5.2 (the paper) refuses the
// point; second-order placement puts it inside face 0, over which it lies, and leaves the edge
// unsplit.
TEST(SharpPoints, APointBeyondTheChordGoesInsideTheFaceThatHoldsIt) {
    const test::Strip s = test::make_strip_past_the_edge();
    const SharpPoints paper =
        test::points_on_edge_a1_b0(s, {.placement = PointPlacement::TangentPlanes});
    EXPECT_EQ(paper.edge_points, 0u);
    EXPECT_EQ(paper.refused_by_flip_test, 1u);

    const SharpPoints ours = test::points_on_edge_a1_b0(s);
    ASSERT_EQ(ours.edge_points, 1u);
    EXPECT_EQ(ours.face_points, 1u);
    EXPECT_EQ(ours.refused_by_flip_test, 0u);
    EXPECT_TRUE(ours.points[0].isApprox(Vec3(0, 0, 0.75), 1e-15));
    PointSlots expected(2);
    expected.set_corner_point(0, 0);
    EXPECT_TRUE(ours.slots == expected);
}

// The spike test on crossing edges: the strip's ends turned 140 degrees apart (the side face's
// normal tilted back over the top) are refused past an edge spike angle of 135, placed at 180 (the
// default); the strip's own right angle passes at 135.
TEST(SharpPoints, TheEdgeSpikeTestRefusesABladeNarrowerThanItsAngle) {
    const test::Strip right = test::make_strip();
    const SharpPointOptions spike{.edge_spike_angle_deg = 135.0};
    const SharpPoints kept = test::points_on_edge_a1_b0(right, spike);
    EXPECT_EQ(kept.edge_points, 1u);
    EXPECT_EQ(kept.refused_by_spike_test, 0u);

    test::Strip blade = test::make_strip();
    const double t = 140.0 * std::numbers::pi / 180.0;
    const Vec3 tilted(std::sin(t), std::cos(t), 0.0);  // 140 degrees from the top's (0, 1, 0)
    blade.set_feature_normals({{0, 1, 0}, {0, 1, 0}, tilted, tilted});
    const SharpPoints refused = test::points_on_edge_a1_b0(blade, spike);
    EXPECT_EQ(refused.edge_points, 0u);
    EXPECT_EQ(refused.refused_by_spike_test, 1u);
    const SharpPoints paper = test::points_on_edge_a1_b0(blade);
    EXPECT_EQ(paper.refused_by_spike_test, 0u);
    EXPECT_EQ(paper.edge_points + paper.refused_by_flip_test, 1u);  // judged by eq. 5.4 alone
}

/// The strip past the edge with a0 moved so that neither face of a1-b0 holds its point.
test::Strip strip_over_neither_face() {
    test::Strip s = test::make_strip_past_the_edge();
    s.mesh.positions[0] = Vec3(-0.3, 0, 1.4);  // face 0 now ends short of z = 0.75 near x = 0
    s.rebuild();
    return s;
}

// Over neither face of the edge nor any face around its ends, the point has nowhere to go.
TEST(SharpPoints, APointOverNoFaceIsRefused) {
    const SharpPoints points = test::points_on_edge_a1_b0(strip_over_neither_face());
    EXPECT_EQ(points.edge_points, 0u);
    EXPECT_EQ(points.face_points, 0u);
    EXPECT_EQ(points.refused_by_flip_test, 1u);
}

// An edge triangle around an end of the edge (b0 here) that lies under the point takes it.
TEST(SharpPoints, APointOverAFaceAroundAnEndGoesInsideIt) {
    test::Strip s = strip_over_neither_face();
    s.mesh.positions.push_back(Vec3(0.5, -0.2, 0.5));
    s.mesh.positions.push_back(Vec3(-0.1, -0.2, 1.5));
    s.mesh.triangles.push_back({2, 4, 5});
    s.rebuild();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    ASSERT_EQ(points.face_points, 1u);
    PointSlots expected(3);
    expected.set_corner_point(2, 0);
    EXPECT_TRUE(points.slots == expected);
    EXPECT_TRUE(points.points[0].isApprox(Vec3(0, 0, 0.75), 1e-15));
}

/// A corner triangle as cut from stepped_block turned off the grid axes (examples/cad, 100 cells,
/// grid pitch 0.73 mm; coordinates less (41.8, 19.2, 39.5)), its neighbours and their exact
/// feature normals: vertex 1 on side a, 0 and 3 on side b, 2, 4 and 5 on side c. Vertices 2
/// and 5 lie 0.02 mm apart (a grid crossing next to a grid node), and vertex 0 lies past the
/// junction of b and c: eq. 5.4 refuses the point of edge 2 (from 2 to 0), and no face holds it.
test::CornerWithNeighbours corner_past_an_edge() {
    const Vec3 a(-0.37957269087502171, 0.89879177246062258, 0.21931238473690393);
    const Vec3 b(-0.9221475172774074, -0.34843169778597549, -0.16804555441039318);
    const Vec3 c(-0.074622575143179576, -0.26602387437045039, 0.96107375863870903);
    return test::CornerWithNeighbours(
        {Vec3(0.10699092408572142, 0.038277367090959302, 0.086567705614690738),
         Vec3(0.0076005163203376469, 0.038277367090959302, -0.38767160394704803),
         Vec3(0.0076005163203376469, -0.6892269921684715, 0.084993370447818961),
         Vec3(0.0076005163203376469, 0.30132065030662147, 0.086567705614690738),
         Vec3(-0.7199038429390896, -0.6892269921684715, 0.028506292085808127),
         Vec3(0.027876581750689411, -0.6892269921684715, 0.086567705614690738)},
        {b, a, c, b, c, c}, {});
}

// The corner point lies past edge 2 of the corner triangle, which has no point of its own: the
// fan around the corner point would fold over that edge (a piece turned against every normal
// around it), and the guard would drop every point of the face. Edge 2 takes the corner point
// too, and the face splits into the four pieces on its sides, each facing its corners' normals.
TEST(SharpPoints, ACornerPointPastAnEdgeWithoutAPointSplitsThatEdge) {
    const test::CornerWithNeighbours c = corner_past_an_edge();
    ASSERT_NE(c.corner(), kNoIndex);
    EXPECT_NE(c.edge(0), kNoIndex);
    EXPECT_NE(c.edge(1), kNoIndex);
    EXPECT_EQ(c.edge(2), c.corner());
    EXPECT_EQ(c.points.slots.edge_point(c.twin(2)), c.corner());
    std::size_t pieces = 0;
    const PieceVertices ids(c.s.mesh, c.points.points);
    for_each_piece(c.s.mesh, c.points.slots, ids, 0, [&](Index u, Index v, Index w) {
        ++pieces;
        const Vec3 n = (ids.position(v) - ids.position(u)).cross(ids.position(w) - ids.position(u));
        for (Index corner : {u, v, w}) {
            if (!ids.is_original(corner)) continue;
            EXPECT_GT(n.dot(c.s.feature_normals.normal(corner)), 0.0);
        }
    });
    EXPECT_EQ(pieces, 4u);
}

/// Two chamfer faces across the edge of a boss of radius 3 standing up to z = 0, moved by
/// `shift`: a0, a1 on the top, b0, b1 on the side, the crossing edge a1-b0; the side's feature
/// normals carry the cylinder's normal field, so second-order placement solves for the point.
test::Strip boss_strip(const Vec3& shift) {
    const double r = 3.0;
    test::Strip s;
    const Vec3 b0(r, 0, -0.4), b1(r * std::cos(0.2), r * std::sin(0.2), -0.35);
    s.mesh.positions = {Vec3(2.6, -0.3, 0) + shift, Vec3(2.6, 0.5, 0) + shift, b0 + shift,
                        b1 + shift};
    s.mesh.triangles = {{0, 2, 1}, {1, 2, 3}};
    s.rebuild();
    s.set_feature_normals(
        {Vec3::UnitZ(), Vec3::UnitZ(), b0.normalized(), Vec3(b1.x(), b1.y(), 0).normalized()});
    s.feature_normals.keep_fields();
    for (Index v : {2, 3}) {
        const Eigen::Matrix3d slope = Eigen::Vector3d(1 / r, 1 / r, 0).asDiagonal();
        s.feature_normals.field_at(v) = {s.feature_normals.normal(v), slope};
    }
    return s;
}

// The junction solve runs about the crossing edge's midpoint with tolerances in its length, so
// the same part 1e4 mm from the origin takes the same steps and gives the same point, moved,
// to far below the solver's tolerance (1e-9 of the edge, 7e-10 mm here): only the last bits of
// the moved coordinates (2e-12 mm at 1e4 mm) differ.
TEST(SharpPoints, SecondOrderPointMovesWithThePart) {
    const SharpPoints base = test::points_on_edge_a1_b0(boss_strip(Vec3::Zero()));
    ASSERT_EQ(base.edge_points, 1u);
    ASSERT_EQ(base.first_order_fallbacks, 0u);
    const test::Strip origin = boss_strip(Vec3::Zero());
    const auto first_order = edge_point(origin.mesh.positions[1], Vec3::UnitZ(),
                                        origin.mesh.positions[2], origin.feature_normals.normal(2));
    ASSERT_TRUE(first_order);
    EXPECT_GT((base.points[0] - *first_order).norm(), 1e-3);  // the solve moved it
    for (const Vec3& shift : {Vec3(1e4, 1e4, 1e4), Vec3(-3.3e3, 7.1e2, 1e4)}) {
        SCOPED_TRACE(shift.x());
        const SharpPoints moved = test::points_on_edge_a1_b0(boss_strip(shift));
        ASSERT_EQ(moved.edge_points, 1u);
        EXPECT_TRUE(moved.slots == base.slots);
        EXPECT_LT((moved.points[0] - shift - base.points[0]).norm(), 2e-11);
    }
}

}  // namespace
}  // namespace resharp
