#include "resharp/restoration/harm_check.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "resharp/core/errors.h"
#include "resharp/eval/self_intersections.h"
#include "resharp/pipeline/restore.h"
#include "strip.h"

namespace resharp {
namespace {

/// The strip split at `point` on edge a1-b0, with no guard in between.
SplitMesh split_at(const test::Strip& s, const Vec3& point) {
    SharpPoints points = test::points_on_edge_a1_b0(s);
    points.points[0] = point;
    return split_faces(s.mesh, points.points, points.slots);
}

TEST(HarmCheck, TheIdealSplitDoesNoHarm) {
    const test::Strip s = test::make_strip();
    const HarmReport r = check_harm(s.surface(), split_at(s, Vec3(0, 0, 0.75)));
    EXPECT_TRUE(r.is_harmless());
    EXPECT_EQ(r.turned + r.folded + r.crossing, 0u);
}

TEST(HarmCheck, APieceTurnedOverIsHarm) {
    const test::Strip s = test::make_strip();
    const HarmReport r = check_harm(s.surface(), split_at(s, Vec3(-2.0, 3.0, 0.75)));
    EXPECT_GE(r.turned, 1u);
    EXPECT_EQ(r.harmful_faces, (std::vector<Index>{0, 1}));
}

TEST(HarmCheck, APieceNearerTheOtherSideOfAThinWallThanItsOwnFaceIsHarm) {
    // A face of another sheet beyond the strip's rings (the other side of a thin wall), facing
    // away from the strip's pieces, 0.06 from the ideal point, which lies farther from the
    // strip's own faces: nearest there, it turns against the pieces, as the do-no-harm
    // criterion counts anywhere in the input, with HarmCheckOptions::beyond_rings; the rings
    // alone do not see it.
    test::Strip s = test::make_strip();
    const Vec3 point(0, 0, 0.75);
    const Vec3 away = Vec3(1, 1, 0).normalized(), along = Vec3(1, -1, 0).normalized();
    const Vec3 centre = point + 0.06 * away;
    s.mesh.positions.push_back(centre + 0.2 * along);
    s.mesh.positions.push_back(centre - 0.2 * along + 0.2 * Vec3::UnitZ());
    s.mesh.positions.push_back(centre - 0.2 * along - 0.2 * Vec3::UnitZ());
    s.mesh.triangles.push_back({4, 5, 6});
    s.rebuild();
    ASSERT_LT(s.normals.face[2].dot(away), -0.99);  // faces away from the pieces
    const auto distance_to = [&](Index f) {
        const Triangle& t = s.mesh.triangles[f];
        return squared_distance_to_triangle(point, s.mesh.positions[t[0]], s.mesh.positions[t[1]],
                                            s.mesh.positions[t[2]]);
    };
    ASSERT_LT(distance_to(2), std::min(distance_to(0), distance_to(1)));
    const SplitMesh split = split_at(s, point);
    const HarmReport r = check_harm(s.surface(), split, {.beyond_rings = true});
    EXPECT_GE(r.turned, 1u);
    EXPECT_EQ(r.harmful_faces, (std::vector<Index>{0, 1}));
    EXPECT_TRUE(check_harm(s.surface(), split).is_harmless());  // the two rings alone
}

TEST(HarmCheck, PiecesFoldedOntoEachOtherAreHarm) {
    // In face 0's plane but beyond its edge a0-b0: piece (a0, M, b0) folds back onto
    // (a0, a1, M), 180 degrees, where the input face was flat.
    const test::Strip s = test::make_strip();
    const Vec3 a0 = s.mesh.positions[0], a1 = s.mesh.positions[1], b0 = s.mesh.positions[2];
    const Vec3 beyond = (a0 + b0) / 2.0 + 0.3 * ((a0 + b0) / 2.0 - a1);
    const SplitMesh out = split_at(s, beyond);
    const HarmReport r = check_harm(s.surface(), out);
    EXPECT_GE(r.folded, 1u);
    EXPECT_FALSE(r.is_harmless());
    EXPECT_THROW(check_harm(s.surface(), out, {.fold_angle_deg = 80.0}), InvalidInput);
}

TEST(HarmCheck, AFaceTurnedByAMovedVertexIsJudgedWhereTheMoveIsGiven) {
    // The strip as its own split, b0 moved where a piece turned over in the test above: its two
    // faces are judged only through the flag, their ids unchanged, against the strip at the
    // input places.
    const test::Strip s = test::make_strip();
    SplitMesh moved;
    moved.mesh = s.mesh;
    moved.mesh.positions[2] = Vec3(-2.0, 3.0, 0.5);
    moved.source_face = {0, 1};
    const Connectivity c = build_connectivity(moved.mesh);
    const SurfaceNormals normals = surface_normals(moved.mesh, c);
    const InputSurface surface{moved.mesh, c, normals};
    const std::vector<Vec3>& input_places = s.mesh.positions;
    const std::vector<std::uint8_t> b0_moved{0, 0, 1, 0};
    const HarmReport r = check_harm(surface, moved, {}, {}, {b0_moved, input_places});
    EXPECT_GE(r.turned, 1u);
    EXPECT_EQ(r.harmful_faces, (std::vector<Index>{0, 1}));
    EXPECT_TRUE(check_harm(s.surface(), moved).is_harmless());  // no face altered, none judged
    const std::vector<std::uint8_t> a0_moved{1, 0, 0, 0};       // a0's faces: face 0 alone
    EXPECT_EQ(check_harm(surface, moved, {}, {}, {a0_moved, input_places}).harmful_faces,
              (std::vector<Index>{0}));
    // The whole faces are judged by the surface given: the input's own say nothing turned.
    EXPECT_TRUE(check_harm(s.surface(), moved, {}, {}, {b0_moved, input_places}).is_harmless());
    const std::vector<std::uint8_t> one_flag{1};
    EXPECT_THROW(check_harm(surface, moved, {}, {}, {one_flag, input_places}), InvalidInput);
    EXPECT_THROW(check_harm(surface, moved, {}, {}, {b0_moved, {}}), InvalidInput);
}

TEST(HarmCheck, AFaceWithAPointLeftOnePieceIsJudgedByItsPieceNotTheMovedFace) {
    // Face 0 (a0, a1, b0) as one piece (b0, a0, c), as two edges snapped onto its corner point
    // leave it, c across the edge a0-b0 from a1: the piece is face 0 turned over. b1 is
    // flagged moved (to where it was), so face 1 is judged whole, by the surface's normal for
    // it; face 0's piece must be judged by its own normal, not the surface's for face 0.
    const test::Strip s = test::make_strip();
    const auto& x = s.mesh.positions;
    SplitMesh split;
    split.mesh.positions = x;
    split.mesh.positions.push_back(x[0] + x[2] - x[1]);
    split.mesh.triangles = {{2, 0, 4}, s.mesh.triangles[1]};
    split.source_face = {0, 1};
    split.point_of_new_vertex = {0};
    split.split_faces = 1;
    split.altered_faces = {0};
    const std::vector<std::uint8_t> b1_moved{0, 0, 0, 1};
    const HarmReport r = check_harm(s.surface(), split, {}, {}, {b1_moved, s.mesh.positions});
    EXPECT_GE(r.turned, 1u);
    EXPECT_EQ(r.harmful_faces, (std::vector<Index>{0}));
    EXPECT_EQ(check_harm(s.surface(), split).harmful_faces, (std::vector<Index>{0}));
}

/// The strip with a triangle hanging from b0 into the space between face 0 and the sharp edge,
/// where the pieces of the split go.
test::Strip strip_with_blocker() {
    test::Strip s = test::make_strip();
    const Vec3 a0 = s.mesh.positions[0], b0 = s.mesh.positions[2], m(0, 0, 0.75);
    const Vec3 inside = (a0 + 2.0 * m + b0) / 4.0;  // on piece (a0, M, b0)
    const Vec3 across = (m - a0).cross(b0 - a0).normalized();
    s.mesh.positions.push_back(inside + 0.1 * across);
    s.mesh.positions.push_back(inside - 0.03 * across);
    s.mesh.triangles.push_back({2, 4, 5});
    s.rebuild();
    return s;
}

TEST(HarmCheck, PiecesCuttingThroughANearbyFaceAreHarmUnlessTheCheckIsOff) {
    const test::Strip s = strip_with_blocker();
    ASSERT_TRUE(eval::self_intersecting_pairs(s.mesh).empty());
    const SplitMesh out = split_at(s, Vec3(0, 0, 0.75));
    ASSERT_FALSE(eval::self_intersecting_pairs(out.mesh).empty());
    const HarmReport r = check_harm(s.surface(), out);
    EXPECT_GE(r.crossing, 1u);
    EXPECT_EQ(r.turned, 0u);
    EXPECT_FALSE(r.is_harmless());
    EXPECT_TRUE(check_harm(s.surface(), out, {.check_crossings = false}).is_harmless());
}

/// `s` with every position scaled by k about the origin.
test::Strip scaled(test::Strip s, double k) {
    for (Vec3& x : s.mesh.positions) x *= k;
    s.rebuild();
    return s;
}

TEST(HarmCheck, VerdictsHoldAtScalesFloatsCannotHold) {
    // The check keeps each split face's box in floats, rounded outward (outer_box.h): beyond the
    // floats' range (1e39) and among their subnormals (1e-40) too, the verdicts are those at 1.
    for (double k : {1e-40, 1e-3, 1.0, 1e3, 1e39}) {
        SCOPED_TRACE(k);
        const test::Strip clean = scaled(test::make_strip(), k);
        EXPECT_TRUE(
            check_harm(clean.surface(), split_at(clean, k * Vec3(0, 0, 0.75))).is_harmless());
        const test::Strip blocked = scaled(strip_with_blocker(), k);
        const HarmReport r = check_harm(blocked.surface(), split_at(blocked, k * Vec3(0, 0, 0.75)));
        EXPECT_GE(r.crossing, 1u);
        EXPECT_EQ(r.turned, 0u);
    }
}

TEST(HarmCheck, RestoreUndoesThePointWhosePiecesCrossAFace) {
    const test::Strip s = strip_with_blocker();
    RestoreOptions options;
    options.features.tiny_patch_faces = 0;
    const FeatureNormals& exact = s.feature_normals;
    BandClassification bands;
    bands.is_crossing.assign(3 * s.mesh.face_count(), 0);
    bands.face_role.assign(s.mesh.face_count(), BandRole::None);
    const SharpPoints wanted = test::points_on_edge_a1_b0(s);
    for (Index h = 0; h < bands.is_crossing.size(); ++h) {
        bands.is_crossing[h] = wanted.slots.edge_point(h) != kNoIndex;
    }
    bands.face_role[0] = bands.face_role[1] = BandRole::Edge;
    const BandRestoration r = restore_bands(s.surface(), bands, exact, options);
    EXPECT_EQ(r.undone_points, 1u);
    EXPECT_EQ(r.rounds, 2u);
    EXPECT_FALSE(r.rounds_exhausted);
    EXPECT_EQ(r.output.mesh.triangles, s.mesh.triangles);
    EXPECT_TRUE(eval::self_intersecting_pairs(r.output.mesh).empty());
}

}  // namespace
}  // namespace resharp
