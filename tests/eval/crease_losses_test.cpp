#include "resharp/eval/crease_losses.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "cube_creases.h"
#include "resharp/core/errors.h"
#include "resharp/eval/exact_creases.h"
#include "support/simple_meshes.h"

namespace resharp::eval {
namespace {

constexpr double kSide = 10.0;
const double kDiagonal = kSide * std::sqrt(3.0);
const CreaseMetricsOptions kOptions{.tolerance = 1e-3, .unit = kDiagonal};  // τ = 0.017 mm

CurveSamples cube_creases() { return test::cube_creases(kSide); }

/// The cube grown by `e` on every side: its edges e sqrt(2) from the true ones.
Mesh grown_cube(double e) {
    Mesh m = test::box_mesh(kSide + 2 * e, kSide + 2 * e, kSide + 2 * e);
    for (Vec3& p : m.positions) p -= Vec3::Constant(e);
    return m;
}

Segmentation every_face(const Mesh& mesh, BandRole role, PointFate fate) {
    Segmentation s;
    s.face_role.assign(mesh.face_count(), role);
    s.point_fate.assign(mesh.face_count(), fate);
    return s;
}

double sum(const std::array<double, kMoveFateCount>& a) {
    return std::accumulate(a.begin(), a.end(), 0.0);
}

TEST(CreaseLosses, ExactCubeLosesNothing) {
    const Mesh cube = test::box_mesh(kSide, kSide, kSide);
    const CreaseLosses l =
        find_crease_losses(cube, cube, every_face(cube, BandRole::None, PointFate::None),
                           cube_creases(), 0.5, 30.0, 0.05, kOptions);
    for (const auto& by_moves : l.missed) EXPECT_EQ(sum(by_moves), 0.0);
    for (std::size_t o = 0; o < kOriginCount; ++o)
        EXPECT_EQ(l.false_beside[o] + l.false_stray[o], 0.0);
    EXPECT_NEAR(l.true_length, 12 * kSide / kDiagonal, 0.01 * 12 * kSide / kDiagonal);
}

TEST(CreaseLosses, OffsetEdgesGetTheFirstStageThatLostThem) {
    const Mesh input = grown_cube(0.1);
    const CurveSamples exact = cube_creases();
    const auto lost_to = [&](const Segmentation& s, double pitch) {
        return find_crease_losses(input, input, s, exact, pitch, 30.0, 0.05, kOptions);
    };
    const std::size_t none = std::size_t(MoveFate::None);
    // No band anywhere: every piece is NoBand; the input's creases, 0.14 mm off, lie beside.
    CreaseLosses l = lost_to(every_face(input, BandRole::None, PointFate::None), 0.5);
    EXPECT_NEAR(l.missed[std::size_t(CreaseLoss::NoBand)][none], l.true_length, 1e-9);
    EXPECT_NEAR(l.false_beside[std::size_t(Origin::Input)], l.mesh_length, 1e-9);
    EXPECT_EQ(l.false_stray[std::size_t(Origin::Input)], 0.0);
    // Within a pitch of 0.1 mm they are strays.
    l = lost_to(every_face(input, BandRole::None, PointFate::None), 0.1);
    EXPECT_NEAR(l.false_stray[std::size_t(Origin::Input)], l.mesh_length, 1e-9);
    for (const auto& [fate, loss] :
         {std::pair{PointFate::NotPlaced, CreaseLoss::NotPlaced},
          std::pair{PointFate::RefusedByGuard, CreaseLoss::RefusedByGuard},
          std::pair{PointFate::UndoneByHarm, CreaseLoss::UndoneByHarm},
          std::pair{PointFate::Inserted, CreaseLoss::InsertedOff}}) {
        l = lost_to(every_face(input, BandRole::Edge, fate), 0.5);
        EXPECT_NEAR(l.missed[std::size_t(loss)][none], l.true_length, 1e-9);
    }
    // Inserted, the faces 0.1 mm off within a pitch of 0.12 mm, the sharp edges 0.14 mm off
    // beyond it.
    l = lost_to(every_face(input, BandRole::Edge, PointFate::Inserted), 0.12);
    EXPECT_NEAR(l.missed[std::size_t(CreaseLoss::InsertedNoCrease)][none], l.true_length, 1e-9);
}

TEST(CreaseLosses, MovedVerticesAreTold) {
    const Mesh input = grown_cube(0.1);
    Mesh output = grown_cube(0.2);
    Segmentation s = every_face(input, BandRole::Edge, PointFate::UndoneByHarm);
    s.move_planned.assign(input.vertex_count(), 1);
    CreaseLosses l =
        find_crease_losses(input, output, s, cube_creases(), 0.5, 30.0, 0.05, kOptions);
    const auto& harm = l.missed[std::size_t(CreaseLoss::UndoneByHarm)];
    EXPECT_NEAR(harm[std::size_t(MoveFate::Kept)], l.true_length, 1e-9);
    EXPECT_NEAR(l.false_beside[std::size_t(Origin::Moves)], l.mesh_length, 1e-9);
    // Planned, none kept.
    l = find_crease_losses(input, input, s, cube_creases(), 0.5, 30.0, 0.05, kOptions);
    EXPECT_NEAR(l.missed[std::size_t(CreaseLoss::UndoneByHarm)][std::size_t(MoveFate::Undone)],
                l.true_length, 1e-9);
    EXPECT_THROW(find_crease_losses(input, output, Segmentation{}, cube_creases(), 0.5, 30.0, 0.05,
                                    kOptions),
                 InvalidInput);
}

TEST(FlippedByOrigin, SplitsTheCountByWhatTurnedTheFace) {
    const Mesh input = test::box_mesh();
    Mesh output = input;
    output.positions[0] += Vec3(0.01, 0.0, 0.0);  // vertex 0 moved
    const Triangle cut = output.triangles[0];
    output.positions.push_back(
        (input.positions[cut[0]] + input.positions[cut[1]] + input.positions[cut[2]]) / 3.0);
    const Index centre = Index(output.positions.size() - 1);
    output.triangles[0] = {cut[0], cut[1], centre};
    output.triangles.push_back({cut[1], cut[2], centre});
    output.triangles.push_back({cut[2], cut[0], centre});
    std::size_t with_vertex_0 = 0;  // unsplit faces at the moved vertex
    for (Index f = 1; f < input.face_count(); ++f) {
        const Triangle& t = input.triangles[f];
        with_vertex_0 += std::find(t.begin(), t.end(), Index{0}) != t.end();
    }
    const std::vector<std::uint8_t> all(output.face_count(), 1);
    std::vector<std::uint8_t> in_input(input.face_count(), 0);
    auto counts = flipped_by_origin(input, output, all, in_input);
    EXPECT_EQ(counts[std::size_t(Origin::Split)], 3u);
    EXPECT_EQ(counts[std::size_t(Origin::Moves)], with_vertex_0);
    EXPECT_EQ(counts[std::size_t(Origin::Input)], input.face_count() - 1 - with_vertex_0);
    // Turned in the input already: counted there, moved or not.
    in_input.assign(input.face_count(), 1);
    counts = flipped_by_origin(input, output, all, in_input);
    EXPECT_EQ(counts[std::size_t(Origin::Moves)], 0u);
    EXPECT_EQ(counts[std::size_t(Origin::Input)], input.face_count() - 1);
    EXPECT_THROW(flipped_by_origin(input, output, in_input, in_input), InvalidInput);
}

}  // namespace
}  // namespace resharp::eval
