#pragma once
/// Two-means clustering of 2-D points (paper eq. 3.1-3.2), used on (k1, k2) per vertex.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace resharp {

struct TwoMeansResult {
    std::vector<std::uint8_t> cluster;  ///< per point: 0 or 1
    std::array<Eigen::Vector2d, 2> centres;
    int iterations = 0;
};

/// Lloyd iterations from the given initial centres until both centres move less than
/// `tolerance` (eq. 3.2) or `max_iterations` is reached. Each step assigns the points in
/// parallel blocks fixed by their count and adds the blocks' sums in order, so the result is
/// bit-identical from run to run and on any number of threads.
TwoMeansResult two_means(const std::vector<Eigen::Vector2d>& points,
                         std::array<Eigen::Vector2d, 2> initial_centres, double tolerance,
                         int max_iterations);

}  // namespace resharp
