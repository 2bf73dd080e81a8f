#include "resharp/segmentation/kmeans.h"

#include <algorithm>

#include "resharp/core/parallel.h"

namespace resharp {
namespace {

/// Points per block of a Lloyd step. The blocks are fixed by the point count alone, and their
/// sums are added in block order, so the centres come out the same bits on any number of threads
/// (a parallel reduction would add in the order the threads finish).
constexpr std::size_t kBlockPoints = 8192;

/// One block's share of a Lloyd step: the sums and counts of its points per cluster.
struct BlockSums {
    std::array<Eigen::Vector2d, 2> sums{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
    std::array<std::size_t, 2> counts{0, 0};
};

/// Assigns every point to its nearer centre (ties to centre 0), writing result.cluster, and
/// gives each block's sums. Bound: one pass over the points.
std::vector<BlockSums> assign(const std::vector<Eigen::Vector2d>& points, TwoMeansResult& result) {
    const std::size_t blocks = (points.size() + kBlockPoints - 1) / kBlockPoints;
    std::vector<BlockSums> out(blocks);
    for_each_index(blocks, 1, [&](std::size_t b) {
        const std::size_t end = std::min(points.size(), (b + 1) * kBlockPoints);
        for (std::size_t i = b * kBlockPoints; i < end; ++i) {
            const std::uint8_t c = (points[i] - result.centres[1]).squaredNorm() <
                                   (points[i] - result.centres[0]).squaredNorm();
            result.cluster[i] = c;
            out[b].sums[c] += points[i];
            ++out[b].counts[c];
        }
    });
    return out;
}

}  // namespace

TwoMeansResult two_means(const std::vector<Eigen::Vector2d>& points,
                         std::array<Eigen::Vector2d, 2> initial_centres, double tolerance,
                         int max_iterations) {
    TwoMeansResult result;
    result.cluster.assign(points.size(), 0);
    result.centres = initial_centres;
    for (int iteration = 1; iteration <= max_iterations; ++iteration) {
        BlockSums total;
        for (const BlockSums& block : assign(points, result)) {  // in block order
            for (int c = 0; c < 2; ++c) {
                total.sums[c] += block.sums[c];
                total.counts[c] += block.counts[c];
            }
        }
        bool converged = true;
        for (int c = 0; c < 2; ++c) {
            if (total.counts[c] == 0) continue;  // an empty cluster keeps its centre
            const Eigen::Vector2d centre = total.sums[c] / static_cast<double>(total.counts[c]);
            converged = converged && (centre - result.centres[c]).norm() < tolerance;
            result.centres[c] = centre;
        }
        result.iterations = iteration;
        if (converged) break;
    }
    return result;
}

}  // namespace resharp
