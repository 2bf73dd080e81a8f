#include "resharp/segmentation/kmeans.h"

namespace resharp {

TwoMeansResult two_means(const std::vector<Eigen::Vector2d>& points,
                         std::array<Eigen::Vector2d, 2> initial_centres, double tolerance,
                         int max_iterations) {
    TwoMeansResult result;
    result.cluster.assign(points.size(), 0);
    result.centres = initial_centres;
    for (int iteration = 1; iteration <= max_iterations; ++iteration) {
        std::array<Eigen::Vector2d, 2> sums{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
        std::array<std::size_t, 2> counts{0, 0};
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::uint8_t c = (points[i] - result.centres[1]).squaredNorm() <
                                   (points[i] - result.centres[0]).squaredNorm();
            result.cluster[i] = c;
            sums[c] += points[i];
            ++counts[c];
        }
        bool converged = true;
        for (int c = 0; c < 2; ++c) {
            if (counts[c] == 0) continue;  // an empty cluster keeps its centre
            const Eigen::Vector2d centre = sums[c] / static_cast<double>(counts[c]);
            converged = converged && (centre - result.centres[c]).norm() < tolerance;
            result.centres[c] = centre;
        }
        result.iterations = iteration;
        if (converged) break;
    }
    return result;
}

}  // namespace resharp
