#include "resharp/segmentation/kmeans.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

namespace resharp {
namespace {

TEST(TwoMeans, SeparatesTwoClustersAndStopsAtTheTolerance) {
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < 90; ++i) points.emplace_back(0.01 * (i % 3), 0.01 * (i % 5));
    for (int i = 0; i < 10; ++i) points.emplace_back(2.0 + 0.01 * i, 3.0);
    const TwoMeansResult r =
        two_means(points, {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)}, 1e-5, 100);
    for (int i = 0; i < 90; ++i) EXPECT_EQ(r.cluster[i], 0);
    for (int i = 90; i < 100; ++i) EXPECT_EQ(r.cluster[i], 1);
    EXPECT_NEAR(r.centres[1].x(), 2.045, 1e-12);
    EXPECT_NEAR(r.centres[1].y(), 3.0, 1e-12);
    EXPECT_LE(r.iterations, 3);  // centres are final after one step; the next confirms it
}

TEST(TwoMeans, KeepsTheCentreOfAnEmptyCluster) {
    const std::vector<Eigen::Vector2d> points(5, Eigen::Vector2d(1, 1));
    const TwoMeansResult r =
        two_means(points, {Eigen::Vector2d(1, 1), Eigen::Vector2d(9, 9)}, 1e-5, 10);
    EXPECT_EQ(r.centres[1], Eigen::Vector2d(9, 9));
    for (auto c : r.cluster) EXPECT_EQ(c, 0);
}

TEST(TwoMeans, GivesTheSameBitsOnOneThreadAsOnSeveral) {
    // Enough points for several blocks, with values whose sums round differently by order.
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < 50000; ++i) {
        const double t = 0.1 * i;
        points.emplace_back(std::sin(t) * (i % 7 == 0 ? 5.0 : 0.3), std::cos(1.3 * t) / 3.0);
    }
    const std::array<Eigen::Vector2d, 2> start{Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0)};
    TwoMeansResult one;
    tbb::task_arena(1).execute([&] { one = two_means(points, start, 1e-12, 50); });
    TwoMeansResult several;
    tbb::task_arena(4).execute([&] { several = two_means(points, start, 1e-12, 50); });
    EXPECT_EQ(one.cluster, several.cluster);
    EXPECT_EQ(one.centres[0], several.centres[0]);
    EXPECT_EQ(one.centres[1], several.centres[1]);
    EXPECT_EQ(one.iterations, several.iterations);
    EXPECT_GT(std::count(one.cluster.begin(), one.cluster.end(), 1), 1000);
}

}  // namespace
}  // namespace resharp
