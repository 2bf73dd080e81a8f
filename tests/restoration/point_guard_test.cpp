#include "resharp/restoration/point_guard.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "resharp/core/errors.h"
#include "resharp/pipeline/restore.h"
#include "strip.h"
#include "support/grid_shapes.h"

namespace resharp {
namespace {

GuardedPoints guard(const test::Strip& s, const SharpPoints& points,
                    std::span<const std::uint8_t> withdrawn = {}) {
    return guard_points(s.surface(), s.feature_normals, points, withdrawn);
}

TEST(Guard, AcceptsTheIdealPoint) {
    const test::Strip s = test::make_strip();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    const GuardedPoints g = guard(s, points);
    EXPECT_EQ(g.accepted.edge_point, points.slots.edge_point);
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
    EXPECT_EQ(points.slots.edge_point[1], 0u);
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
    ASSERT_GT(piece.dot(s.feature_normals.normal[0]), 0.0);
    ASSERT_LT(piece.dot(s.normals.face[0]), 0.0);
    const GuardedPoints g = guard(s, points);
    EXPECT_EQ(g.report.refused_by_guard, 1u);
    EXPECT_EQ(g.report.refused_by_quality, 0u);
    EXPECT_FALSE(g.accepted.has_points(0));
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
        place_sharp_points(shape.mesh, d.connectivity, d.normals.face, d.bands, d.feature_normals);

    JitteredPlate(unsigned seed, double spread) {
        std::mt19937 random(seed);
        std::normal_distribution<double> jitter(0.0, spread * shape.pitch);
        for (Vec3& p : points.points) p += Vec3(jitter(random), jitter(random), jitter(random));
    }
    InputSurface surface() const { return d.surface(shape.mesh); }
};

/// Every point of a sampled drilled plate's bands thrown off its place at random: many faces need
/// repairs, and the work stays within the bound the guard states (three repairs per slot
/// holding a point at the start), taking points away only.
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
    for (Index h = 0; h < g.accepted.edge_point.size(); ++h) {
        const Index p = g.accepted.edge_point[h];
        const bool kept_or_snapped = p == kNoIndex || p == points.slots.edge_point[h] ||
                                     p >= points.edge_points;  // snapped onto a corner point
        EXPECT_TRUE(kept_or_snapped) << "half-edge " << h;
    }
}

/// A later round's guard, which guards again only the parts of the band that lost a point, gives
/// what a full guard gives for the same withdrawals: slots, counts and repairs, over two rounds
/// of random withdrawals from jittered points (which need many repairs to start with).
TEST(Guard, AGuardAgainEqualsAFullGuard) {
    const JitteredPlate plate(11, 0.3);
    const InputSurface surface = plate.surface();
    const Detection& d = plate.d;
    const SharpPoints& points = plate.points;
    std::mt19937 random(11);
    GuardedPoints last = guard_points(surface, d.feature_normals, points, {});
    ASSERT_GT(last.report.repairs, 10u);
    std::vector<std::uint8_t> before, now(points.points.size(), 0);
    std::vector<Index> every_face(plate.shape.mesh.face_count());
    std::iota(every_face.begin(), every_face.end(), Index{0});
    std::bernoulli_distribution withdraw(0.05);
    for (int round = 0; round < 2; ++round) {
        for (std::uint8_t& w : now) w = w || withdraw(random);
        const GuardedPoints full = guard_points(surface, d.feature_normals, points, now);
        const GuardedPoints again =
            guard_points_again(surface, d.feature_normals, points, last, before, now, every_face);
        EXPECT_EQ(again.accepted.edge_point, full.accepted.edge_point) << "round " << round;
        EXPECT_EQ(again.accepted.corner_point, full.accepted.corner_point) << "round " << round;
        EXPECT_EQ(again.report.refused_by_quality, full.report.refused_by_quality);
        EXPECT_EQ(again.report.refused_by_guard, full.report.refused_by_guard);
        EXPECT_EQ(again.report.repairs, full.report.repairs);
        EXPECT_EQ(again.repairs.size(), full.repairs.size());
        before = now;
        last = again;
    }
    // A withdrawal changes something, or the test would prove nothing.
    EXPECT_NE(last.accepted.edge_point,
              guard_points(surface, d.feature_normals, points, {}).accepted.edge_point);
}

TEST(Guard, AGuardAgainChecksItsFlags) {
    const test::Strip s = test::make_strip();
    const SharpPoints points = test::points_on_edge_a1_b0(s);
    const GuardedPoints first = guard(s, points);
    const std::vector<std::uint8_t> one{1}, wrong_size{1, 0};
    const std::vector<Index> face_0{0}, face_9{9};
    EXPECT_FALSE(guard_points_again(s.surface(), s.feature_normals, points, first, {}, one, face_0)
                     .accepted.has_points(0));
    EXPECT_THROW(
        guard_points_again(s.surface(), s.feature_normals, points, first, wrong_size, one, face_0),
        InvalidInput);
    EXPECT_THROW(
        guard_points_again(s.surface(), s.feature_normals, points, first, {}, wrong_size, face_0),
        InvalidInput);
    EXPECT_THROW(guard_points_again(s.surface(), s.feature_normals, points, first, {}, one, face_9),
                 InvalidInput);
}

}  // namespace
}  // namespace resharp
