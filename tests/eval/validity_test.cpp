#include "resharp/eval/validity.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "resharp/core/errors.h"
#include "resharp/pipeline/restore.h"
#include "support/grid_shapes.h"
#include "support/harm_criteria.h"

namespace resharp::eval {
namespace {

// A regular tetrahedron, outward oriented.
Mesh tetrahedron() {
    return {{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)},
            {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
}

TEST(Validity, ClosedTetrahedron) {
    const MeshValidity v = check_validity(tetrahedron());
    EXPECT_EQ(v.triangles, 4u);
    EXPECT_EQ(v.boundary_edges, 0u);
    EXPECT_EQ(v.nonmanifold_edges, 0u);
    EXPECT_EQ(v.inconsistent_edges, 0u);
    EXPECT_EQ(v.self_intersections, 0u);
    EXPECT_NEAR(v.min_angle_deg, 60.0, 1e-9);
}

TEST(Validity, OpenFlippedAndCrossing) {
    Mesh open = tetrahedron();
    open.triangles.pop_back();
    EXPECT_EQ(check_validity(open).boundary_edges, 3u);
    Mesh flipped = tetrahedron();
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    EXPECT_EQ(check_validity(flipped).inconsistent_edges, 3u);
    // Two triangles piercing each other.
    const Mesh crossing{{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0.5, 0.5, -1),
                         Vec3(0.5, 0.5, 1), Vec3(1.5, 1.5, 0.5)},
                        {{0, 1, 2}, {3, 4, 5}}};
    EXPECT_EQ(check_validity(crossing).self_intersections, 1u);
}

// One input face on z = 0 with exact normals +z. The output replaces it by three faces around
// a new centre vertex, one of them turned over, plus a face of new vertices only.
TEST(Validity, FlippedFacesAgainstExactNormals) {
    const Mesh input{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}};
    const Oracle oracle{{Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ()}, {0, 0, 0}};
    SurfaceSamples exact{{Vec3(0.3, 0.3, 0)}, {Vec3::UnitZ()}};
    Mesh output = input;
    output.positions.push_back(Vec3(0.3, 0.3, 0));                    // 3
    output.positions.push_back(Vec3(0.35, 0.3, 0));                   // 4
    output.positions.push_back(Vec3(0.3, 0.35, 0));                   // 5
    output.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 3, 0}, {3, 5, 4}};  // {2,3,0} and {3,5,4}: -z
    EXPECT_EQ(count_flipped_faces(input, output, oracle, exact, FlipScope::ChangedFaces), 2u);
    // The input itself: no face flipped; with one vertex's normal reversed, its face is, unless
    // the samples where it lies face its way.
    EXPECT_EQ(count_flipped_faces(input, input, oracle, exact, FlipScope::AllFaces), 0u);
    EXPECT_EQ(count_flipped_faces(input, input, oracle, exact, FlipScope::ChangedFaces), 0u);
    Oracle reversed = oracle;
    reversed.normals[1] = -Vec3::UnitZ();
    EXPECT_EQ(count_flipped_faces(input, input, reversed, SurfaceSamples{}, FlipScope::AllFaces),
              1u);
    EXPECT_EQ(count_flipped_faces(input, input, reversed, exact, FlipScope::AllFaces), 0u);
    EXPECT_THROW(count_flipped_faces(input, output, Oracle{}, exact, FlipScope::AllFaces),
                 InvalidInput);
}

// A vertex beside or on a 90 degree edge carries the other face's normal (+x) though its face
// lies on z = 0: an off-surface mesher's vertex, one on the edge itself (a grid line crossing
// the edge), a bisection vertex h/512 off. Judged where the face lies, the face is not flipped,
// and its reversal is; without samples only the vertex test can judge it.
TEST(Validity, FlippedFacesOfVerticesOnTheOtherSurfaceWhereTheyLie) {
    const Mesh input{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}};
    const Oracle on_surface{{Vec3::UnitX(), Vec3::UnitZ(), Vec3::UnitZ()}, {1, 0, 0}};
    Oracle off_surface = on_surface;
    off_surface.surface_points = {Vec3(0, 0, 0.1), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    Oracle barely_off = on_surface;
    barely_off.surface_points = {Vec3(0, 0, 1e-3), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const SurfaceSamples exact{{Vec3(0.3, 0.3, 0), Vec3(5, 0.3, 0.3)},
                               {Vec3::UnitZ(), Vec3::UnitX()}};
    Mesh reversed = input;
    std::swap(reversed.triangles[0][1], reversed.triangles[0][2]);
    for (const Oracle& oracle : {on_surface, off_surface, barely_off}) {
        EXPECT_EQ(count_flipped_faces(input, input, oracle, exact, FlipScope::AllFaces), 0u);
        EXPECT_EQ(count_flipped_faces(input, reversed, oracle, exact, FlipScope::AllFaces), 1u);
    }
    EXPECT_EQ(count_flipped_faces(input, input, on_surface, SurfaceSamples{}, FlipScope::AllFaces),
              1u);
}

// A face of an off-surface mesher on the top (z = 0) of a convex 90 degree edge, 0.1 above it
// and overhanging the wall (x = 0), rising 2.5 degrees towards the wall, as restoration beside
// such an edge leaves it. Its centroid is nearest a wall sample (+x, 0.136 away; the face turns
// 92.5 degrees against it), a top sample (+z) 0.146 away. Judged against the samples within
// the nearest distance plus the face's own offset from the surface (0.166), it is not flipped;
// were its vertices only 0.008 off their surface points, it would be.
TEST(Validity, FlippedFacesBesideAnEdgeWithinTheMeshersOffset) {
    const Mesh input{{Vec3(-0.1, 0, 0.1), Vec3(0.125, -0.5, 0.11), Vec3(0.125, 0.5, 0.11)},
                     {{0, 1, 2}}};
    const Oracle oracle{{Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ()},
                        {0, 0, 0},
                        {Vec3(-0.1, 0, 0), Vec3(0, -0.5, 0), Vec3(0, 0.5, 0)}};
    const SurfaceSamples exact{{Vec3(0, 0, -0.02), Vec3(-0.05, 0, 0)},
                               {Vec3::UnitX(), Vec3::UnitZ()}};
    EXPECT_EQ(count_flipped_faces(input, input, oracle, exact, FlipScope::AllFaces), 0u);
    Oracle barely_off = oracle;  // 0.008 off: judged at the centroid, with almost no tie
    for (Index v = 0; v < 3; ++v) {
        barely_off.surface_points[v] = input.positions[v] - Vec3(0, 0, 0.008);
    }
    EXPECT_EQ(count_flipped_faces(input, input, barely_off, exact, FlipScope::AllFaces), 1u);
    // Unless the samples lie 0.01 apart: the surface point nearest it may be that far from the
    // nearest sample, so the top's sample is as near.
    SurfaceSamples spaced = exact;
    spaced.spacing = 0.01;
    EXPECT_EQ(count_flipped_faces(input, input, barely_off, spaced, FlipScope::AllFaces), 0u);
    // Turned over, it turns against the top; with the wall's sample gone nothing excuses it.
    const Mesh turned_over{input.positions, {{0, 2, 1}}};
    const SurfaceSamples top{{Vec3(-0.05, 0, 0)}, {Vec3::UnitZ()}};
    EXPECT_EQ(count_flipped_faces(input, turned_over, oracle, top, FlipScope::AllFaces), 1u);
}

// A unit square on z = 0 (+z) as input. Pieces of one of its faces around a new vertex are not
// turned against it, one of them reversed is; so is a face whose corners are an input face's
// but one of which moved across the others. Faces left as they were are not judged.
TEST(Validity, TurnedAgainstInput) {
    const Mesh input{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
                     {{0, 1, 2}, {0, 2, 3}}};
    const auto count = [&](const Mesh& output) {
        const std::vector<std::uint8_t> turned = turned_against_input(input, output);
        EXPECT_EQ(turned.size(), output.face_count());
        return std::count(turned.begin(), turned.end(), 1);
    };
    EXPECT_EQ(count(input), 0);
    Mesh split = input;
    split.positions.push_back(Vec3(0.7, 0.3, 0));
    split.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 0, 4}, {0, 2, 3}};
    EXPECT_EQ(count(split), 0);
    split.triangles[0] = {0, 4, 1};
    EXPECT_EQ(count(split), 1);
    Mesh moved = input;
    moved.positions[1] = Vec3(0.2, 0.9, 0);
    EXPECT_EQ(count(moved), 1);
    EXPECT_THROW(turned_against_input(input, Mesh{{Vec3(0, 0, 0)}, {}}), InvalidInput);
}

// The grid search agrees with the tests' brute-force one (support/harm_criteria.h) on restored
// plates, of an exact mesher and of one whose vertices restore() moves, with every fifth piece
// turned over.
TEST(Validity, TurnedAgainstInputAgreesWithTheBruteForceSearch) {
    for (sim::Mesher mesher : {sim::Mesher::MarchingCubes, sim::Mesher::Midpoint}) {
        SCOPED_TRACE(sim::to_string(mesher));
        const test::SampledShape shape = test::sampled_drilled_plate(0.5, mesher);
        RestoreResult r = restore(shape.mesh, RestoreOptions{});
        const auto count = [&] {
            const std::vector<std::uint8_t> turned = turned_against_input(shape.mesh, r.mesh);
            return static_cast<std::size_t>(std::count(turned.begin(), turned.end(), 1));
        };
        EXPECT_EQ(count(), test::turned_against_nearest(shape.mesh, r.mesh, r.source_face));
        std::size_t pieces = 0;
        for (Index f = 0; f < r.mesh.face_count(); ++f) {
            Triangle& t = r.mesh.triangles[f];
            if (t != shape.mesh.triangles[r.source_face[f]] && pieces++ % 5 == 0) {
                std::swap(t[1], t[2]);
            }
        }
        ASSERT_GT(pieces, 100u);
        EXPECT_GE(count(), pieces / 5);
        EXPECT_EQ(count(), test::turned_against_nearest(shape.mesh, r.mesh, r.source_face));
    }
}

}  // namespace
}  // namespace resharp::eval
