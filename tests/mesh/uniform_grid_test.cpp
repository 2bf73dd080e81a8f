#include "resharp/mesh/uniform_grid.h"

#include <gtest/gtest.h>

#include <random>

namespace resharp {
namespace {

using detail::Box3;
using detail::UniformGrid;

std::vector<Vec3> random_points(std::size_t n, double scale, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, scale);
    std::vector<Vec3> p(n);
    for (Vec3& x : p) x = Vec3(u(rng), u(rng), u(rng));
    return p;
}

// Nearest by shells agrees with brute force, for queries inside, near and far outside the
// points, dense and sparse sets (the sparse one falls back to a scan).
TEST(UniformGrid, NearestMatchesBruteForce) {
    for (const std::size_t count : {std::size_t{5}, std::size_t{2000}}) {
        const auto points = random_points(count, 10.0, 1);
        const UniformGrid grid(
            count, [&](std::size_t i) { return Box3(points[i], points[i]); }, 0.5);
        for (const Vec3& q : random_points(200, 30.0, 2)) {
            const Vec3 p = q - Vec3::Constant(10.0);
            double best = 1e300;
            for (const Vec3& x : points) best = std::min(best, (x - p).norm());
            const auto [i, d] = grid.nearest(p, [&](Index k) { return (points[k] - p).norm(); });
            EXPECT_DOUBLE_EQ(d, best);
            EXPECT_DOUBLE_EQ((points[i] - p).norm(), best);
        }
    }
}

TEST(UniformGrid, ForEachNearVisitsEveryItemWithinRadius) {
    const auto points = random_points(3000, 5.0, 3);
    const UniformGrid grid(
        points.size(), [&](std::size_t i) { return Box3(points[i], points[i]); }, 0.3);
    const Vec3 p(2.5, 2.5, 2.5);
    std::vector<bool> seen(points.size(), false);
    grid.for_each_near(p, 0.7, [&](Index k) { seen[k] = true; });
    for (std::size_t k = 0; k < points.size(); ++k) {
        if ((points[k] - p).norm() <= 0.7) {
            EXPECT_TRUE(seen[k]) << k;
        }
    }
}

// Every item whose box meets the query box is visited, boxes spanning several cells included,
// and for a query box off the grid's side too.
TEST(UniformGrid, ForEachMeetingVisitsEveryItemWhoseBoxMeetsTheBox) {
    const auto corners = random_points(2000, 5.0, 5);
    auto box_of = [&](std::size_t i) {
        return Box3(corners[i], corners[i] + Vec3(0.4, 0.1, 0.7) * double(i % 3));
    };
    const UniformGrid grid(corners.size(), box_of, 0.3);
    for (const Box3& query : {Box3(Vec3(1.0, 2.0, 0.5), Vec3(1.6, 2.2, 3.0)),
                              Box3(Vec3(-2.0, 3.5, 3.5), Vec3(0.6, 9.0, 9.0))}) {
        std::vector<bool> seen(corners.size(), false);
        grid.for_each_meeting(query, [&](Index k) { seen[k] = true; });
        std::size_t meeting = 0;
        for (std::size_t k = 0; k < corners.size(); ++k) {
            if (!box_of(k).intersects(query)) continue;
            ++meeting;
            EXPECT_TRUE(seen[k]) << k;
        }
        EXPECT_GT(meeting, 5u);
    }
}

TEST(UniformGrid, EmptyGridHasNoNearest) {
    const UniformGrid grid(
        0, [](std::size_t) { return Box3(); }, 1.0);
    EXPECT_EQ(grid.nearest(Vec3::Zero(), [](Index) { return 0.0; }).first, kNoIndex);
}

}  // namespace
}  // namespace resharp
