#include "resharp/surfaces/plane_fit.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "resharp/surfaces/local_quadric.h"

namespace resharp {

namespace {

/// The covariance of the points about their mean `centre`. Six sums of products, not a 3x3
/// outer product added per point: the compiler kept each point's product in memory and read it
/// back, and the loop waited on those reads (60 % of fit_plane()'s time, which the moves' planning
/// calls 26,000 times on mech by OpenVDB). The same sums in the same order: the same bits.
Eigen::Matrix3d covariance_about(std::span<const Vec3> points, const Vec3& centre) {
    double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
    for (const Vec3& p : points) {
        const Vec3 d = p - centre;
        xx += d.x() * d.x();
        xy += d.x() * d.y();
        xz += d.x() * d.z();
        yy += d.y() * d.y();
        yz += d.y() * d.z();
        zz += d.z() * d.z();
    }
    Eigen::Matrix3d covariance;
    covariance << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return covariance / static_cast<double>(points.size());
}

}  // namespace

std::optional<PlaneFit> fit_plane(std::span<const Vec3> points, const Vec3& facing) {
    if (points.size() < 3) return std::nullopt;
    PlaneFit fit;
    for (const Vec3& p : points) fit.centroid += p;
    fit.centroid /= static_cast<double>(points.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
        covariance_about(points, fit.centroid));
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

namespace {

/// The covariance of the points' coordinates in the plane of `fit` (tangent_frame() axes,
/// about their centroid).
Eigen::Matrix2d covariance_in_plane(std::span<const Vec3> points, const PlaneFit& fit) {
    const Eigen::Matrix3d frame = tangent_frame(fit.plane.normal);
    Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
    for (const Vec3& p : points) {
        const Vec3 d = p - fit.centroid;
        const Eigen::Vector2d q(frame.col(0).dot(d), frame.col(1).dot(d));
        covariance += q * q.transpose();
    }
    return covariance;
}

/// Whether the points lie on at most two parallel lines of the plane of `fit`, `gap` (mm) apart
/// or less: any two such lines lie in one plane, which then says nothing of a face. The line
/// through the first point and the most others (their directions from it, as angles in the
/// plane, equal to a millionth of a radian) gives the direction; across it the points take two
/// values or fewer. Bound: a sort of the points.
bool on_two_lines(std::span<const Vec3> points, const PlaneFit& fit, double gap) {
    if (points.size() < 3) return true;
    const Eigen::Matrix3d frame = tangent_frame(fit.plane.normal);
    std::vector<double> angles;
    angles.reserve(points.size() - 1);
    for (std::size_t i = 1; i < points.size(); ++i) {
        const Vec3 d = points[i] - points[0];
        double angle = std::atan2(frame.col(1).dot(d), frame.col(0).dot(d));
        if (angle < 0.0) angle += std::numbers::pi;  // a line's direction, either way along it
        if (angle >= std::numbers::pi) angle -= std::numbers::pi;
        angles.push_back(angle);
    }
    std::sort(angles.begin(), angles.end());
    constexpr double kSameAngle = 1e-6;
    std::size_t best = 0, run = 0;
    double along = angles[0];
    for (std::size_t i = 0; i < angles.size(); ++i) {
        run = i > 0 && angles[i] - angles[i - 1] <= kSameAngle ? run + 1 : 1;
        if (run > best) best = run, along = angles[i];
    }
    const Vec3 across = -std::sin(along) * frame.col(0) + std::cos(along) * frame.col(1);
    std::vector<double> values;
    values.reserve(points.size());
    for (const Vec3& p : points) values.push_back(across.dot(p - points[0]));
    std::sort(values.begin(), values.end());
    std::size_t distinct = 1;
    for (std::size_t i = 1; i < values.size(); ++i) distinct += values[i] - values[i - 1] > gap;
    return distinct <= 2;
}

}  // namespace

double in_plane_spread(std::span<const Vec3> points, const PlaneFit& fit) {
    // The eigenvalues of a symmetric 2 x 2 matrix in closed form, mean -+ radius: an
    // eigensolver per fit cost the near moves on mech by surface nets 17 M instructions.
    const Eigen::Matrix2d c = covariance_in_plane(points, fit);
    const double mean = 0.5 * (c(0, 0) + c(1, 1));
    const double radius = std::hypot(0.5 * (c(0, 0) - c(1, 1)), c(0, 1));
    return mean + radius > 0.0 ? std::max(mean - radius, 0.0) / (mean + radius) : 0.0;
}

std::optional<PlaneFit> fit_plane_trimmed(std::span<const Vec3> points, const Vec3& facing,
                                          const PlaneFit& first, double exact,
                                          std::size_t min_points, std::vector<Vec3>& kept) {
    const std::size_t least = std::max<std::size_t>({min_points, (points.size() + 1) / 2, 3});
    kept.assign(points.begin(), points.end());
    PlaneFit fit = first;
    // Bound: each round drops a tenth of the points kept, one at least, and the rounds end
    // before fewer than half are left: about seven rounds.
    while (fit.rms_distance > exact) {
        const std::size_t keep = kept.size() - std::max<std::size_t>(1, kept.size() / 10);
        if (keep < least) return std::nullopt;
        const Plane plane = fit.plane;
        std::nth_element(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(keep), kept.end(),
                         [&](const Vec3& a, const Vec3& b) {
                             return std::abs(plane.signed_distance(a)) <
                                    std::abs(plane.signed_distance(b));
                         });
        kept.resize(keep);
        const std::optional<PlaneFit> next = fit_plane(kept, facing);
        if (!next) return std::nullopt;
        fit = *next;
    }
    return fit;
}

std::optional<PlaneFit> fit_plane_of_most(std::span<const Vec3> points, const Vec3& facing,
                                          const PlaneFit& first, double exact,
                                          std::size_t min_points, std::vector<Vec3>& kept) {
    std::optional<PlaneFit> fit = fit_plane_trimmed(points, facing, first, exact, min_points, kept);
    if (fit && on_two_lines(kept, *fit, 10.0 * exact)) return std::nullopt;
    return fit;
}

std::optional<HeightFit> fit_height_quadric(std::span<const Vec3> points, const Plane& plane,
                                            const Vec3& at) {
    constexpr std::size_t kMinPoints = 10;  // six unknowns, with some to spare against noise
    if (points.size() < kMinPoints) return std::nullopt;
    const Vec3 foot = plane.projection(at);
    const Eigen::Matrix3d frame = tangent_frame(plane.normal);
    const Vec3 t1 = frame.col(0), t2 = frame.col(1);
    double scale = 0.0;  // the points' reach, so the rank test does not depend on units
    for (const Vec3& p : points) {
        const Vec3 d = p - foot;
        scale = std::max({scale, std::abs(d.dot(t1)), std::abs(d.dot(t2))});
    }
    if (!(scale > 0.0)) return std::nullopt;
    // One row per point, in units of the reach: 1, u, v, u^2, u v, v^2 against the height.
    auto row = [&](const Vec3& p) {
        const Vec3 d = p - foot;
        const double u = d.dot(t1) / scale, v = d.dot(t2) / scale;
        return Eigen::Vector<double, 6>{1.0, u, v, u * u, u * v, v * v};
    };
    // The normal equations: a fixed 6 x 6 system, where a QR of the n x 6 rows cost the midpoint
    // moves, which test every fit, two fifths of restore()'s instructions on mech. The columns
    // are scaled to the reach, so squaring their condition stays far from rounding.
    Eigen::Matrix<double, 6, 6> gram = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Vector<double, 6> moment = Eigen::Vector<double, 6>::Zero();
    for (const Vec3& p : points) {
        const Eigen::Vector<double, 6> r = row(p);
        gram.noalias() += r * r.transpose();
        moment += r * (p - foot).dot(plane.normal);
    }
    // Points near one line or conic of the plane do not fix the six coefficients: a pivot of
    // the Gram matrix's factorization vanishes against the largest (1e-12: the QR's 1e-6 on
    // the rows, squared).
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> factors(gram);
    const Eigen::Vector<double, 6> pivots = factors.vectorD().cwiseAbs();
    if (factors.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff()))
        return std::nullopt;
    const Eigen::Vector<double, 6> coefficients = factors.solve(moment);
    double residual = 0.0;
    for (const Vec3& p : points) {
        const double r = row(p).dot(coefficients) - (p - foot).dot(plane.normal);
        residual += r * r;
    }
    return HeightFit{foot + coefficients[0] * plane.normal,
                     std::sqrt(residual / static_cast<double>(points.size())),
                     foot,
                     frame,
                     scale,
                     coefficients};
}

SurfaceValue HeightFit::evaluate(const Vec3& p) const {
    const Vec3 local = frame.transpose() * (p - foot);
    const double u = local.x() / scale, v = local.y() / scale;
    const Eigen::Vector<double, 6>& c = coefficients;
    const double height = c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
    const double slope_u = (c[1] + 2.0 * c[3] * u + c[4] * v) / scale;
    const double slope_v = (c[2] + c[4] * u + 2.0 * c[5] * v) / scale;
    return {local.z() - height, frame * Vec3(-slope_u, -slope_v, 1.0)};
}

}  // namespace resharp
