#include "resharp/surfaces/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace resharp {

std::optional<PlaneFit> fit_plane(std::span<const Vec3> points, const Vec3& facing) {
    if (points.size() < 3) return std::nullopt;
    PlaneFit fit;
    for (const Vec3& p : points) fit.centroid += p;
    fit.centroid /= static_cast<double>(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Vec3& p : points) {
        const Vec3 d = p - fit.centroid;
        covariance += d * d.transpose();
    }
    covariance /= static_cast<double>(points.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    // Eigenvalues ascending. Points on a line have two vanishing ones: the normal is then any
    // direction across the line, not a plane's.
    const Eigen::Vector3d spread = solver.eigenvalues();
    if (solver.info() != Eigen::Success || !(spread[1] > 1e-12 * spread[2])) return std::nullopt;
    Vec3 normal = solver.eigenvectors().col(0);
    if (normal.dot(facing) < 0.0) normal = -normal;
    fit.plane = {normal, normal.dot(fit.centroid)};
    fit.rms_distance = std::sqrt(std::max(spread[0], 0.0));
    return fit;
}

}  // namespace resharp
