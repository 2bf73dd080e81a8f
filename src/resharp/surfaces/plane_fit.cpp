#include "resharp/surfaces/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "resharp/surfaces/local_quadric.h"

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

std::optional<HeightFit> fit_height_quadric(std::span<const Vec3> points, const Plane& plane,
                                            const Vec3& at) {
    constexpr std::size_t kMinPoints = 10;  // six unknowns, with some to spare against noise
    if (points.size() < kMinPoints) return std::nullopt;
    const Vec3 foot = plane.projection(at);
    const Eigen::Matrix3d frame = tangent_frame(plane.normal);
    const Vec3 t1 = frame.col(0), t2 = frame.col(1);
    const Eigen::Index n = static_cast<Eigen::Index>(points.size());
    Eigen::MatrixXd design(n, 6);
    Eigen::VectorXd height(n);
    double scale = 0.0;  // the points' reach, so the rank test does not depend on units
    for (Eigen::Index i = 0; i < n; ++i) {
        const Vec3 d = points[static_cast<std::size_t>(i)] - foot;
        const double u = d.dot(t1), v = d.dot(t2);
        scale = std::max({scale, std::abs(u), std::abs(v)});
        design.row(i) << 1.0, u, v, u * u, u * v, v * v;
        height[i] = d.dot(plane.normal);
    }
    if (!(scale > 0.0)) return std::nullopt;
    // Columns in units of the reach: well scaled, so the QR's rank threshold means the geometry.
    const Eigen::Vector<double, 6> unit{1.0,           scale,         scale,
                                        scale * scale, scale * scale, scale * scale};
    design = design * unit.cwiseInverse().asDiagonal();
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
    qr.setThreshold(1e-6);
    if (qr.rank() < 6) return std::nullopt;
    const Eigen::VectorXd coefficients = qr.solve(height);
    const double residual = (design * coefficients - height).squaredNorm();
    return HeightFit{foot + coefficients[0] * plane.normal,
                     std::sqrt(residual / static_cast<double>(n))};
}

}  // namespace resharp
