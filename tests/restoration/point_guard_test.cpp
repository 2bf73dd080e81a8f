#include "resharp/restoration/point_guard.h"

#include <gtest/gtest.h>

#include <array>
#include <numbers>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "resharp/core/errors.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/pipeline/restore.h"
#include "resharp/restoration/split.h"
#include "strip.h"
#include "support/grid_shapes.h"

namespace resharp {
namespace {

GuardedPoints guard(const test::Strip& s, const SharpPoints& points,
                    std::span<const std::uint8_t> withdrawn = {}) {
    return guard_points(s.surface(), s.feature_normals, points, withdrawn);
}

/// The split's diagnostics, after expecting it manifold, consistently oriented and without
/// degenerate faces.
MeshDiagnostics expect_sound(const SplitMesh& split) {
    const MeshDiagnostics d = diagnose(split.mesh, build_connectivity(split.mesh));
    EXPECT_EQ(d.nonmanifold_edges, 0u);
    EXPECT_EQ(d.inconsistent_edges, 0u);
    EXPECT_EQ(d.degenerate_faces, 0u);
    return d;
}

TEST(Guard, AcceptsTheIdealPoint) {
    const test::Strip s = test::make_strip();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    const GuardedPoints g = guard(s, points);
    EXPECT_TRUE(g.accepted == points.slots);
    EXPECT_EQ(g.report.repairs, 0u);
}

TEST(Guard, DropsAPointWhoseSplitWouldTurnAPieceOver) {
    const test::Strip s = test::make_strip();
    SharpPoints points = test::points_on_edge_a1_b0(s);
    points.points[0] = Vec3(-2.0, 3.0, 0.75);  // far off: pieces would flip
    const GuardedPoints g = guard(s, points);
    EXPECT_EQ(g.report.refused_by_quality, 1u);
    EXPECT_FALSE(g.accepted.has_points(0));
    EXPECT_FALSE(g.accepted.has_points(1));
    // The guard changes nothing it is given.
    EXPECT_EQ(points.slots.edge_point(1), 0u);
}

TEST(Guard, RefusesAPieceTurnedAgainstTheFaceItReplaces) {
    // Off the ideal (0, 0, 0.75) towards -x, the point keeps piece (a0, a1, M) on the side of
    // the top's normal, as a wrong feature normal would, but folds it back over face 0 (the
    // paper's flip: M' projects outside the face it comes from).
    const test::Strip s = test::make_strip();
    SharpPoints points = test::points_on_edge_a1_b0(s);
    points.points[0] = Vec3(-0.2225, 0.1, 0.75);
    const Vec3 piece =
        (s.mesh.positions[1] - s.mesh.positions[0]).cross(points.points[0] - s.mesh.positions[0]);
    ASSERT_GT(piece.dot(s.feature_normals.normal(0)), 0.0);
    ASSERT_LT(piece.dot(s.normals.face[0]), 0.0);
    const GuardedPoints g = guard(s, points);
    EXPECT_EQ(g.report.refused_by_guard, 1u);
    EXPECT_EQ(g.report.refused_by_quality, 0u);
    EXPECT_FALSE(g.accepted.has_points(0));
}

// Where a sharp edge ends at a corner, eq. 5.2's mid-plane can put the edge's point past the
// corner point, on the edge's extension: here the vertical edge runs up from the corner
// (-0.414, 0, 0.586) to its next point at z = 1, and the point of edge 1 lies below the corner,
// at z = 0.5; the pieces of face 0 between them fold. The corner point is kept and edge 1 split
// at it rather than the corner point dropped (the guard used to drop it, the first single point
// whose loss mends the face), which would leave the corner without a point and keep a point
// that restores nothing of its edge.
TEST(Guard, SplitsAnEdgeAtTheCornerPointRatherThanDropIt) {
    const Vec3 up(0, 0, 1), front(0, -1, 0), left(-1, 0, 0);
    const test::CornerWithNeighbours c(
        {Vec3(-1, 0.414, 0.586), Vec3(0, 0, 0), Vec3(-0.414, 0.414, 1), Vec3(-1, 0, 0),
         Vec3(0, 0, 1), Vec3(-1, 1.414, 0.586)},
        {up, front, left, front, front, up},
        {{4, Vec3(-1, 0, 0.586)}, {8, Vec3(-0.414, 0, 1)}, {10, Vec3(-0.414, 0.914, 0.586)}});
    ASSERT_EQ(c.points.corner_points, 1u);
    ASSERT_NE(c.corner(), kNoIndex);
    EXPECT_TRUE(c.points.points[c.corner()].isApprox(Vec3(-0.414, 0, 0.586), 1e-12));
    EXPECT_TRUE(c.points.points[c.edge(1)].isApprox(Vec3(-0.414, 0, 0.5), 1e-12));
    const GuardedPoints g = guard(c.s, c.points);
    EXPECT_EQ(g.accepted.corner_point(0), c.corner());
    EXPECT_EQ(g.accepted.edge_point(1), c.corner());
    EXPECT_EQ(g.accepted.edge_point(c.twin(1)), c.corner());
    EXPECT_EQ(g.accepted.edge_point(0), c.edge(0));
    EXPECT_EQ(g.accepted.edge_point(2), c.edge(2));
    EXPECT_EQ(g.report.refused_by_quality + g.report.refused_by_guard, 0u);
}

// The two edges' points of face 0 both past the corner point (0.586, 0, -0.414): the vertical
// edge 1's below it, edge 2's beside it. No single edge split at the corner point mends the
// face, and the guard used to drop all four of its points. Splitting both edges at it keeps the
// corner point, and the split mesh is oriented and manifold: vertex 2 is joined to the corner
// point by faces 2 and 3 alone.
TEST(Guard, SplitsTwoEdgesAtTheCornerPointWhereOneIsNotEnough) {
    const Vec3 up(0, 0, 1), back(0, 1, 0), right(1, 0, 0);
    const test::CornerWithNeighbours c(
        {Vec3(0, 0.414, -0.414), Vec3(0, 0, 0), Vec3(0.586, -0.586, -1), Vec3(-1, 0, 0),
         Vec3(0.586, -0.586, 0), Vec3(0.586, 0.414, -1)},
        {up, back, right, back, right, right},
        {{4, Vec3(-0.5, 0, -0.414)}, {7, Vec3(0.586, 0, 0)}, {11, Vec3(0.586, 0.414, -0.414)}});
    ASSERT_NE(c.corner(), kNoIndex);
    EXPECT_TRUE(c.points.points[c.corner()].isApprox(Vec3(0.586, 0, -0.414), 1e-12));
    const GuardedPoints g = guard(c.s, c.points);
    EXPECT_EQ(g.accepted.corner_point(0), c.corner());
    EXPECT_EQ(g.accepted.edge_point(0), c.edge(0));
    EXPECT_EQ(g.accepted.edge_point(1), c.corner());
    EXPECT_EQ(g.accepted.edge_point(c.twin(1)), c.corner());
    EXPECT_EQ(g.accepted.edge_point(2), c.corner());
    EXPECT_EQ(g.accepted.edge_point(c.twin(2)), c.corner());
    EXPECT_EQ(g.report.refused_by_quality + g.report.refused_by_guard, 0u);
    const SplitMesh split = split_faces(c.s.mesh, c.points.points, g.accepted);
    EXPECT_EQ(expect_sound(split).nonmanifold_vertices, 0u);
}

// A corner of mixed convexity, as cut from stepped_block turned 27 degrees at 100 cells (turned
// back; a pitch is 0.73 mm): the slot's walls x = 0 and y = 0 (a concave edge up z) meet the
// bottom z = 0 (two convex rims), the slot being x < 0, y > 0. The point of the corner
// triangle's edge 0 lies beyond its chord, inside face 1, and the corner point goes on that
// edge instead; vertex 3 of face 1 lies past the rim's end, so face 1's fan around its inner
// point turns a piece over. The guard used to drop the corner point from edge 0 (the first
// single point whose loss mends face 1), after which the corner triangle's pieces turned over
// and it lost all its points; it now drops face 1's inner point, which lies on the line from
// the corner point to face 1's other edge point, and every other point is kept.
TEST(Guard, KeepsTheCornerPointOnAnEdgeAndDropsThePointInsideTheFaceAcross) {
    const Vec3 left(-1, 0, 0), down(0, 0, -1), back(0, 1, 0);
    const test::CornerWithNeighbours c(
        {Vec3(0, 0.537, 0.604), Vec3(-0.026, -0.113, 0), Vec3(-0.722, 0, 0.579),
         Vec3(0.145, 0.302, 0), Vec3(-0.761, 0, 0.103), Vec3(-0.537, 0, 0.82)},
        {left, down, back, down, back, back},
        {{4, Vec3(0, 0.419, 0)}, {7, Vec3(-0.39, 0, 0)}, {11, Vec3(0, 0, 0.72)}});
    ASSERT_NE(c.corner(), kNoIndex);
    EXPECT_TRUE(c.points.points[c.corner()].isZero(1e-12));
    ASSERT_EQ(c.edge(0), c.corner());
    const Index inside = c.points.slots.corner_point(1);
    ASSERT_NE(inside, kNoIndex);
    ASSERT_LT(inside, c.points.edge_points);
    const GuardedPoints g = guard(c.s, c.points);
    EXPECT_EQ(g.accepted.corner_point(0), c.corner());
    EXPECT_EQ(g.accepted.edge_point(0), c.corner());
    EXPECT_EQ(g.accepted.edge_point(1), c.edge(1));
    EXPECT_EQ(g.accepted.edge_point(2), c.edge(2));
    EXPECT_EQ(g.accepted.corner_point(1), kNoIndex);
    EXPECT_EQ(g.report.refused_by_quality + g.report.refused_by_guard, 1u);
    const SplitMesh split = split_faces(c.s.mesh, c.points.points, g.accepted);
    expect_sound(split);
}

/// A patch cut from a mesh around a corner of mixed convexity, turned back to the grid axes with
/// the corner at the origin, where three planes through the origin meet: its vertices, the plane
/// each lies on (an index into `planes`, their outward normals), and its faces. Its feature
/// normals are the planes' normals, every edge between planes crosses, and the points are
/// placed by eq. 5.2-5.3 (the crossing edges on the patch's border, which eq. 5.2 leaves alone,
/// hold none).
struct CornerPatch {
    test::Strip s;
    SharpPoints points;
    std::array<Vec3, 3> planes;

    CornerPatch(std::vector<Vec3> positions, const std::vector<int>& plane_of,
                std::vector<Triangle> triangles, const std::array<Vec3, 3>& normals)
        : planes(normals) {
        s.mesh.positions = std::move(positions);
        s.mesh.triangles = std::move(triangles);
        s.rebuild();
        std::vector<Vec3> given;
        for (int k : plane_of) given.push_back(planes[static_cast<std::size_t>(k)]);
        s.set_feature_normals(given);
        BandClassification bands;
        for (const Triangle& t : s.mesh.triangles) {
            const int sides =
                1 + int(plane_of[t[0]] != plane_of[t[1]]) +
                int(plane_of[t[2]] != plane_of[t[0]] && plane_of[t[2]] != plane_of[t[1]]);
            bands.face_role.push_back(sides == 3   ? BandRole::Corner
                                      : sides == 2 ? BandRole::Edge
                                                   : BandRole::None);
        }
        for (Index h = 0; h < 3 * s.mesh.face_count(); ++h) {
            bands.is_crossing.push_back(plane_of[tail_vertex(s.mesh, h)] !=
                                        plane_of[head_vertex(s.mesh, h)]);
        }
        points =
            place_sharp_points(s.mesh, s.connectivity, s.normals.face, bands, s.feature_normals);
    }

    /// The faces of the split the guard lets through (expected sound) with a corner within
    /// `reach` of the corner that do not lie on one of the planes (bevels left across it).
    std::size_t bevels_near_the_corner_after_guard(double reach) const {
        const GuardedPoints g = guard(s, points);
        const SplitMesh split = split_faces(s.mesh, points.points, g.accepted);
        expect_sound(split);
        std::size_t bevels = 0;
        for (const Triangle& t : split.mesh.triangles) {
            bool near = false;
            for (Index v : t) near = near || split.mesh.positions[v].norm() <= reach;
            bool on_a_plane = false;
            for (const Vec3& n : planes) {
                bool on = true;
                for (Index v : t) on = on && std::abs(split.mesh.positions[v].dot(n)) < 1e-9;
                on_a_plane = on_a_plane || on;
            }
            bevels += near && !on_a_plane;
        }
        return bevels;
    }
};

// The corner where a slot's walls x = 0 and y = 0 (a concave edge down z) meet the step's floor
// z = 0 (two convex rims), the slot being x > 0, y < 0: cut from stepped_block turned 27 degrees
// at 100 cells (mm; a pitch is 0.6). The corner triangle's edges to the floor vertex at
// (-0.49, 0.21) hold points past the corner, on the rims' extensions, and the corner point goes
// on them instead; the next face along the rim y = 0 holds a point 0.01 mm past the corner. The
// guard used to drop the corner point from their shared edge, a point snapped there: merged
// with the other, it restores the corner, and no face near it is left a bevel.
TEST(Guard, MergesAPointBesideACornerOfMixedConvexityIntoTheCornerPoint) {
    const CornerPatch c({{0.0000, -0.8583, -0.2497},
                         {0.0000, -0.1001, -0.4228},
                         {0.0000, -0.4573, -0.3413},
                         {0.1773, 0.0000, -0.4766},
                         {0.5911, 0.9116, 0.0000},
                         {0.9552, 0.0000, -0.6126},
                         {-0.7727, -0.4848, 0.0000},
                         {-0.0923, -0.7486, 0.0000},
                         {-0.4853, 0.2132, 0.0000},
                         {0.0000, -0.3051, -1.1154},
                         {-0.1980, 0.9113, 0.0000},
                         {0.4824, 0.6475, 0.0000}},
                        {0, 0, 0, 1, 2, 1, 2, 2, 2, 0, 2, 2},
                        {{2, 9, 1},
                         {9, 3, 1},
                         {5, 3, 9},
                         {8, 6, 1},
                         {6, 2, 1},
                         {6, 7, 2},
                         {2, 7, 0},
                         {3, 8, 1},
                         {3, 10, 8},
                         {3, 11, 10},
                         {5, 11, 3},
                         {10, 11, 4}},
                        {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)});
    EXPECT_EQ(c.bevels_near_the_corner_after_guard(0.3), 0u);
}

// The corner where a pocket's walls x = 0 and y = 0 (a concave edge down z) meet the top z = 0
// (two convex rims), the pocket being x > 0, y < 0: cut from stepped_block turned 27 degrees at
// 100 cells (mm). The corner triangle's edge to the top holds the corner point (its own lies
// past its chord); the face across it reaches from the top at (0.36, 0.62) down the wall x = 0,
// across the rim x = 0 where it no longer runs (y > 0, past the corner), and that edge's point,
// 0.08 mm past the corner on the rim's extension, lies inside the next face. The guard used to
// drop the corner point, after which the corner triangle lost every point; the corner point
// goes on that edge too, the point past the corner goes, and no face near it is left a bevel.
TEST(Guard, PutsTheCornerPointOnTheEdgeThatCrossesARimPastItsCorner) {
    const CornerPatch c(
        {{0.0000, -0.4080, -1.2156}, {0.0000, -0.9563, -0.3335}, {0.0000, -0.1981, -0.5066},
         {0.3644, 0.6200, 0.0000},   {-0.4951, 1.2786, 0.0000},  {0.1047, 0.8190, 0.0000},
         {0.4443, 0.0000, -1.3864},  {0.0000, -1.3019, -0.2547}, {0.5047, 0.0000, -0.6400},
         {0.7044, 0.3595, 0.0000},   {1.2826, 0.0000, -0.7760},  {1.3430, 0.0000, -0.0296},
         {-1.1852, -0.3981, 0.0000}, {-0.5049, -0.6619, 0.0000}, {-0.8979, 0.2999, 0.0000},
         {-0.2176, 0.0362, 0.0000},  {-0.6106, 0.9980, 0.0000},  {0.0698, 0.7342, 0.0000},
         {0.7501, 0.4705, 0.0000},   {1.4305, 0.2067, 0.0000},   {0.3571, 1.4323, 0.0000}},
        {0, 0, 0, 2, 2, 2, 1, 0, 1, 2, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 2},
        {{2, 1, 0},  {6, 8, 0},   {8, 2, 0},    {13, 7, 1},   {13, 14, 12}, {13, 15, 14},
         {2, 13, 1}, {2, 15, 13}, {15, 16, 14}, {15, 17, 16}, {8, 9, 2},    {9, 3, 2},
         {3, 15, 2}, {3, 17, 15}, {10, 11, 8},  {11, 9, 8},   {16, 5, 4},   {16, 17, 5},
         {5, 17, 3}, {9, 18, 3},  {11, 19, 9},  {19, 18, 9},  {5, 20, 4},   {20, 5, 3}},
        {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)});
    EXPECT_EQ(c.bevels_near_the_corner_after_guard(0.3), 0u);
}

/// A band face that leans past the plane of its lone corner, as marching cubes leave them beside
/// a concave edge of a turned block (cut from stepped_block turned 27 degrees at 200 cells; mm,
/// about the edge): the top y = 0 (a, u) and the side x = 0 (b, c, w) meet along z. Face 0 (a, b,
/// c) faces the side but 8 degrees against the top, so the points of its edges a-b and c-a, on the
/// sharp edge 0.01 mm apart, lie in the wrong order along it: the ear (p_ca, a, p_ab) turns over.
/// The guard used to drop one point and then the other's faces' points, leaving the band unrestored
/// beside both edges; one point on both edges cuts a off with no ear, and every point is kept.
TEST(Guard, PutsTwoPointsOutOfOrderOnBothEdgesAsOne) {
    test::Strip s;
    s.mesh.positions = {{0.2766, 0, 0.2966},
                        {0, 0.0178, 0.0068},
                        {0, 0.1148, -0.0123},
                        {0.3603, 0, 0.0934},
                        {0, 0.3826, 0.0670}};
    s.mesh.triangles = {{0, 1, 2}, {3, 1, 0}, {0, 2, 4}};
    const Vec3 top(0, 1, 0), side(1, 0, 0);
    s.given_normals = {top, side, side, top, side};
    s.rebuild();
    ASSERT_LT(s.normals.face[0].dot(top), -0.1);
    BandClassification bands;
    bands.is_crossing.assign(3 * s.mesh.face_count(), 0);
    bands.face_role.assign(s.mesh.face_count(), BandRole::Edge);
    for (Index h = 0; h < bands.is_crossing.size(); ++h) {
        const Index u = tail_vertex(s.mesh, h), v = head_vertex(s.mesh, h);
        bands.is_crossing[h] = s.given_normals[u] != s.given_normals[v];
    }
    SharpPoints points =
        place_sharp_points(s.mesh, s.connectivity, s.normals.face, bands, s.feature_normals);
    // The crossing edges on the border (u-b, w-a), which eq. 5.2 leaves alone: the band goes
    // on there, as on the part.
    for (Index h : {3u, 8u}) {
        const Index u = tail_vertex(s.mesh, h), v = head_vertex(s.mesh, h);
        points.points.push_back(*edge_point(s.mesh.positions[u], s.given_normals[u],
                                            s.mesh.positions[v], s.given_normals[v]));
        points.slots.set_edge_point(h, static_cast<Index>(points.points.size() - 1));
    }
    points.edge_points = points.points.size();
    const Index ab = points.slots.edge_point(0), ca = points.slots.edge_point(2);
    ASSERT_NE(ab, kNoIndex);
    ASSERT_NE(ca, kNoIndex);
    const Vec3& a = s.mesh.positions[0];
    const Vec3 ear = (a - points.points[ca]).cross(points.points[ab] - points.points[ca]);
    ASSERT_LT(ear.dot(top), 0.0);  // both points: the ear turns over

    const GuardedPoints g = guard(s, points);
    EXPECT_EQ(g.report.refused_by_quality + g.report.refused_by_guard, 0u);
    EXPECT_EQ(g.accepted.edge_point(0), g.accepted.edge_point(2));
    EXPECT_TRUE(g.accepted.edge_point(0) == ab || g.accepted.edge_point(0) == ca);
    for (Index h = 0; h < 3 * s.mesh.face_count(); ++h) {  // every edge keeps a point
        EXPECT_EQ(g.accepted.edge_point(h) != kNoIndex, points.slots.edge_point(h) != kNoIndex);
    }
    const SplitMesh split = split_faces(s.mesh, points.points, g.accepted);
    expect_sound(split);
    for (const Triangle& t : split.mesh.triangles) {  // each piece faces its input corners' side
        const Vec3 n = triangle_normal(split.mesh.positions[t[0]], split.mesh.positions[t[1]],
                                       split.mesh.positions[t[2]]);
        for (Index v : t) {
            if (v < s.mesh.vertex_count()) {
                EXPECT_GT(n.dot(s.given_normals[v]), 0.99);
            }
        }
    }
}

/// A near-surface vertex moved onto a sharp edge, as surface nets leave one in the cell the
/// edge crosses: c (0) on the edge along x, with no feature normal, its vertex normal leaning
/// 65 degrees from the top z = 0 towards the side y = 0 (it has more faces there); b (1) on the
/// top, a (2) and d (3) on the side. Face 0 (b, c, a) has the crossing edge a-b, whose point
/// `point` splits it into a piece on the side (c, a, point) and one on the top
/// (c, point, b).
struct VertexOnTheEdge {
    test::Strip s;
    SharpPoints points;

    explicit VertexOnTheEdge(const Vec3& point) {
        const Vec3 top(0, 0, 1), side(0, -1, 0);
        s.mesh.positions = {{0, 0, 0}, {0.5, 0.3, 0}, {0.7, 0, -0.3}, {-0.5, 0, -0.3}};
        s.mesh.triangles = {{1, 0, 2}, {0, 3, 2}};
        s.rebuild();
        s.set_feature_normals({Vec3::Zero(), top, side, side});
        const double lean = 65.0 * std::numbers::pi / 180.0;
        s.normals.vertex[0] = Vec3(0, -std::sin(lean), std::cos(lean));
        points.points = {point};
        points.slots = PointSlots(s.mesh.face_count());
        points.slots.set_edge_point(crossing_edge(), 0);
        points.edge_points = 1;
    }
    Index crossing_edge() const { return 2; }  ///< face 0's half-edge a -> b
};

// The piece on the top faces 65 degrees from c's vertex normal, more than the 60 its reference
// allows, but it lies on the side next to c that b's feature normal gives: the point is taken
// (before, the guard refused it and left a notch in the restored edge).
TEST(Guard, AcceptsAPieceOnASideNextToAVertexMovedOntoTheEdge) {
    const VertexOnTheEdge e(Vec3(0.6, 0, 0));
    ASSERT_EQ(tail_vertex(e.s.mesh, e.crossing_edge()), 2u);
    ASSERT_EQ(head_vertex(e.s.mesh, e.crossing_edge()), 1u);
    const GuardedPoints g = guard(e.s, e.points);
    EXPECT_TRUE(g.accepted == e.points.slots);
    EXPECT_EQ(g.report.refused_by_quality + g.report.refused_by_guard, 0u);
}

// The same vertex still refuses a piece that lies on no side: with the point moved off the edge
// to (0.6, 0.45, 0) the top piece turns over (it faces -z); at (0.6, 0, 0.15) it leans 26
// degrees from the top, more than a side's normal may be off, and faces 88 from c's normal.
TEST(Guard, RefusesAPieceOnNoSideNextToAVertexWithoutAFeatureNormal) {
    for (const Vec3& point : {Vec3(0.6, 0.45, 0), Vec3(0.6, 0, 0.15)}) {
        const VertexOnTheEdge e(point);
        const GuardedPoints g = guard(e.s, e.points);
        EXPECT_FALSE(g.accepted.has_points(0)) << point.transpose();
        EXPECT_EQ(g.report.refused_by_quality, 1u) << point.transpose();
    }
}

TEST(Guard, WithdrawnPointsAreNotAccepted) {
    const test::Strip s = test::make_strip();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    const std::vector<std::uint8_t> withdrawn{1};
    EXPECT_FALSE(guard(s, points, withdrawn).accepted.has_points(0));
    const std::vector<std::uint8_t> wrong_size{1, 0};
    EXPECT_THROW(guard(s, points, wrong_size), InvalidInput);
}

/// A sampled drilled plate, its detection, and its band points each thrown off its place by a
/// normal jitter of `spread` pitches per coordinate (from `seed`).
struct JitteredPlate {
    test::SampledShape shape = test::sampled_drilled_plate();
    Detection d = detect_bands(shape.mesh, build_connectivity(shape.mesh), {});
    SharpPoints points =
        place_sharp_points(shape.mesh, *d.connectivity, d.normals.face, d.bands, d.feature_normals);

    JitteredPlate(unsigned seed, double spread) {
        std::mt19937 random(seed);
        std::normal_distribution<double> jitter(0.0, spread * shape.pitch);
        for (Vec3& p : points.points) p += Vec3(jitter(random), jitter(random), jitter(random));
    }
    InputSurface surface() const { return d.surface(shape.mesh); }
};

/// Every point of a sampled drilled plate's bands thrown off its place at random: many faces need
/// repairs, and the work stays within the bound the guard states (three repairs per slot
/// holding a point at the start), taking points away only: a slot keeps its point, loses it, or
/// takes a point a face of its edge held (a corner point snapped onto, another edge's point
/// merged with).
TEST(Guard, RepairsStayWithinTheirBoundWhenEveryPointIsWrong) {
    const JitteredPlate plate(7, 1.0);
    const test::SampledShape& shape = plate.shape;
    const SharpPoints& points = plate.points;
    ASSERT_GT(points.points.size(), 50u);
    std::size_t slots = 0;
    for (Index f = 0; f < shape.mesh.face_count(); ++f) {
        points.slots.for_each_point(f, [&](Index) { ++slots; });
    }
    const GuardedPoints g = guard_points(plate.surface(), plate.d.feature_normals, points, {});
    EXPECT_GT(g.report.repairs, 20u);
    EXPECT_LE(g.report.repairs, 3 * slots);
    auto held_by = [&](Index f, Index p) {
        bool held = false;
        points.slots.for_each_point(f, [&](Index q) { held = held || q == p; });
        return held;
    };
    for (Index h = 0; h < 3 * g.accepted.face_count(); ++h) {
        const Index p = g.accepted.edge_point(h);
        if (p == kNoIndex || p == points.slots.edge_point(h)) continue;
        const Index twin = plate.d.connectivity->twin[h];
        EXPECT_TRUE(held_by(face_of(h), p) || (twin != kNoIndex && held_by(face_of(twin), p)))
            << "half-edge " << h;
    }
}

/// A later round's guard, which guards again only the parts of the band that lost a point, gives
/// what a full guard gives for the same withdrawals: slots, counts and repairs, over rounds of
/// random withdrawals from jittered points (which need many repairs to start with). Points
/// thrown far (0.3 h) and many withdrawn at once make large regions; points thrown a little
/// (0.1 h) and few withdrawn make repairs cascade past a region's border, so that the guard
/// must set the run's slots back and guard a larger region again (in each of the 9 rounds
/// of those, as counted when this test was written).
void expect_guard_again_equals_full_guard(unsigned seed, double spread, double withdrawal) {
    const JitteredPlate plate(seed, spread);
    const InputSurface surface = plate.surface();
    const Detection& d = plate.d;
    const SharpPoints& points = plate.points;
    std::mt19937 random(seed);
    GuardedPoints last = guard_points(surface, d.feature_normals, points, {});
    ASSERT_GT(last.report.repairs, 10u);
    std::vector<std::uint8_t> before, now(points.points.size(), 0);
    std::vector<Index> every_face(plate.shape.mesh.face_count());
    std::iota(every_face.begin(), every_face.end(), Index{0});
    std::bernoulli_distribution withdraw(withdrawal);
    for (int round = 0; round < 3; ++round) {
        for (std::uint8_t& w : now) w = w || withdraw(random);
        const GuardedPoints full = guard_points(surface, d.feature_normals, points, now);
        const GuardedPoints again = guard_points_again(surface, d.feature_normals, points, last,
                                                       before, now, every_face, {});
        EXPECT_TRUE(again.accepted == full.accepted) << "round " << round;
        EXPECT_EQ(again.report.refused_by_quality, full.report.refused_by_quality);
        EXPECT_EQ(again.report.refused_by_guard, full.report.refused_by_guard);
        EXPECT_EQ(again.report.repairs, full.report.repairs);
        EXPECT_EQ(again.repairs.size(), full.repairs.size());
        before = now;
        last = again;
    }
    // A withdrawal changes something, or the test would prove nothing.
    EXPECT_FALSE(last.accepted == guard_points(surface, d.feature_normals, points, {}).accepted);
}

TEST(Guard, AGuardAgainEqualsAFullGuard) {
    expect_guard_again_equals_full_guard(11, 0.3, 0.05);
    for (unsigned seed : {1u, 2u, 3u}) expect_guard_again_equals_full_guard(seed, 0.1, 0.03);
}

/// Near-surface restoration puts moved vertices back between rounds: a guard again told the
/// faces within three rings of them (`reshaped`) gives what a full guard gives on the surface as
/// it now is, though no point was withdrawn.
TEST(Guard, AGuardAgainAfterVerticesMovedEqualsAFullGuard) {
    const JitteredPlate plate(5, 0.1);
    const Detection& d = plate.d;
    const Connectivity& connectivity = *d.connectivity;
    const SharpPoints& points = plate.points;
    const GuardedPoints first = guard_points(plate.surface(), d.feature_normals, points, {});
    // Every fifth corner of the faces holding candidates, moved by about a third of a pitch.
    Mesh mesh = plate.shape.mesh;
    std::vector<Index> shifted;
    std::vector<std::uint8_t> seen(mesh.vertex_count(), 0);
    std::size_t corners = 0;
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (!points.slots.has_points(f)) continue;
        for (Index v : mesh.triangles[f]) {
            if (seen[v]++ || corners++ % 5 != 0) continue;
            mesh.positions[v] += Vec3(0.2, -0.1, 0.25) * plate.shape.pitch;
            shifted.push_back(v);
        }
    }
    ASSERT_GT(shifted.size(), 20u);
    const std::vector<Index> reshaped = faces_within_rings(mesh, connectivity, shifted, 3);
    const SurfaceNormals normals = surface_normals(mesh, connectivity);
    const InputSurface surface{mesh, connectivity, normals};
    const std::vector<std::uint8_t> none(points.points.size(), 0);
    const GuardedPoints full = guard_points(surface, d.feature_normals, points, none);
    const GuardedPoints again =
        guard_points_again(surface, d.feature_normals, points, first, {}, none, {}, reshaped);
    ASSERT_FALSE(full.accepted == first.accepted);  // the moves change something
    EXPECT_TRUE(again.accepted == full.accepted);
    EXPECT_EQ(again.report.refused_by_quality, full.report.refused_by_quality);
    EXPECT_EQ(again.report.refused_by_guard, full.report.refused_by_guard);
    EXPECT_EQ(again.report.repairs, full.report.repairs);
}

TEST(Guard, AGuardAgainChecksItsFlags) {
    const test::Strip s = test::make_strip();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    const GuardedPoints first = guard(s, points);
    const std::vector<std::uint8_t> one{1}, wrong_size{1, 0};
    const std::vector<Index> face_0{0}, face_9{9};
    EXPECT_FALSE(
        guard_points_again(s.surface(), s.feature_normals, points, first, {}, one, face_0, {})
            .accepted.has_points(0));
    EXPECT_THROW(guard_points_again(s.surface(), s.feature_normals, points, first, wrong_size, one,
                                    face_0, {}),
                 InvalidInput);
    EXPECT_THROW(guard_points_again(s.surface(), s.feature_normals, points, first, {}, wrong_size,
                                    face_0, {}),
                 InvalidInput);
    EXPECT_THROW(
        guard_points_again(s.surface(), s.feature_normals, points, first, {}, one, face_9, {}),
        InvalidInput);
}

}  // namespace
}  // namespace resharp
