#include "resharp/segmentation/kmeans.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace resharp
