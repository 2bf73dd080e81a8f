#pragma once
/// Where implicit surfaces meet: the point of the curve where two surfaces meet nearest a target
/// (a crossing edge's ideal point), and the point where three meet (a corner's). Both are found
/// by bounded Newton iterations with a convergence check, never by sampling. Used on the exact
/// surfaces of a part (eval/exact_junctions.h) and on surfaces fitted to a mesh
/// (surfaces/local_quadric.h), so one solver places and scores the points.
///
/// Templates, because each caller's surface type is its own (the exact forms of the simulator,
/// a fitted quadric) and is evaluated a few times per point: a virtual call per evaluation would
/// cost more than the evaluation of a plane.

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <optional>

#include "resharp/core/types.h"

namespace resharp {

/// An implicit function's value and gradient at a point; the surface is where the value is 0.
struct SurfaceValue {
    double value = 0.0;
    Vec3 gradient = Vec3::Zero();
};

/// A surface given by an implicit function.
template <class S>
concept ImplicitFunction = requires(const S& surface, const Vec3& p) {
    { surface.evaluate(p) } -> std::same_as<SurfaceValue>;
};

struct JunctionSolverOptions {
    double pitch = 0.5;       ///< h, mm: the unit of the two lengths below
    int max_iterations = 60;  ///< bound on Newton steps; no convergence by then is a failure
    /// In h: converged when every surface's value over its gradient's length (a first-order
    /// distance from it) and the last step are below this.
    double tolerance = 1e-8;
    double max_step = 1.0;  ///< in h: longest single step
};

namespace junction_detail {

/// Gradients closer to parallel than this (sine of the angle) meet in no single curve.
inline constexpr double kMinSine = 1e-6;
/// The secant slope of lambda is held at or below this: near zero or positive it would send the
/// step far off (a target near the curve's centre of curvature).
inline constexpr double kMaxSlope = -0.1;

/// The largest first-order distance from p to any of the surfaces (value over gradient length).
template <std::size_t N>
double residual(const std::array<SurfaceValue, N>& values) {
    double worst = 0.0;
    for (const SurfaceValue& s : values) {
        const double g = s.gradient.norm();
        worst = std::max(worst, g > 0.0 ? std::abs(s.value) / g : INFINITY);
    }
    return worst;
}

inline Vec3 clamp_length(const Vec3& step, double longest) {
    const double n = step.norm();
    return n > longest ? Vec3(step * (longest / n)) : step;
}

}  // namespace junction_detail

/// Takes two surfaces, a target point and a starting point; gives the point of the curve where
/// the surfaces meet nearest `target` (a local minimum of the distance, found from `start`), or
/// nothing if the iteration does not converge within its bound or the surfaces are parallel
/// there (no single curve). For two planes and the midpoint of a crossing edge as target this
/// is eq. 5.2's point: on both planes and on the plane through the target normal to their line.
template <ImplicitFunction A, ImplicitFunction B>
std::optional<Vec3> edge_junction(const A& a, const B& b, const Vec3& target, const Vec3& start,
                                  const JunctionSolverOptions& options = {}) {
    using namespace junction_detail;
    const double h = options.pitch, tolerance = options.tolerance * h;
    const double longest = options.max_step * h;
    Vec3 x = start;
    // Each step either moves x onto both surfaces (the least-norm Newton step) or, once it is
    // there, along the curve's tangent towards the point nearest the target: Newton's method on
    // lambda(s) = (target - x(s)) · t(s), the distance's derivative along the curve. Its slope
    // is -1 on a straight junction; on a curved one it is estimated from the last two steps
    // (a secant), without which the steps overshoot by the ratio of the target's distance to
    // the curve's radius and diverge beyond twice it.
    double last_lambda = 0.0, last_step = 0.0;
    Vec3 last_t = Vec3::Zero();
    for (int k = 0; k < options.max_iterations; ++k) {
        const std::array<SurfaceValue, 2> f{a.evaluate(x), b.evaluate(x)};
        const Vec3 tangent = f[0].gradient.cross(f[1].gradient);
        const double scale = f[0].gradient.norm() * f[1].gradient.norm();
        if (!(tangent.norm() > kMinSine * scale)) return std::nullopt;
        if (residual(f) > tolerance) {
            Eigen::Matrix<double, 2, 3> j;
            j.row(0) = f[0].gradient.transpose();
            j.row(1) = f[1].gradient.transpose();
            const Eigen::Vector2d values(f[0].value, f[1].value);
            const Eigen::Matrix2d normal = j * j.transpose();
            x -= clamp_length(j.transpose() * normal.inverse() * values, longest);
            continue;
        }
        Vec3 t = tangent.normalized();
        // Keep the tangent's orientation from step to step, so lambdas compare.
        if (t.dot(last_t) < 0.0) t = -t;
        const double lambda = (target - x).dot(t);
        if (std::abs(lambda) <= tolerance) return x;
        double slope = -1.0;
        if (last_step != 0.0) slope = std::min((lambda - last_lambda) / last_step, kMaxSlope);
        const double step = std::clamp(-lambda / slope, -longest, longest);
        x += step * t;
        last_lambda = lambda;
        last_step = step;
        last_t = t;
    }
    return std::nullopt;
}

/// Takes three surfaces and a starting point; gives the point where all three meet nearest
/// `start` by Newton's method, or nothing if it does not converge within its bound or two of
/// the surfaces are parallel there.
template <ImplicitFunction A, ImplicitFunction B, ImplicitFunction C>
std::optional<Vec3> corner_junction(const A& a, const B& b, const C& c, const Vec3& start,
                                    const JunctionSolverOptions& options = {}) {
    using namespace junction_detail;
    const double h = options.pitch, tolerance = options.tolerance * h;
    Vec3 x = start;
    for (int k = 0; k < options.max_iterations; ++k) {
        const std::array<SurfaceValue, 3> f{a.evaluate(x), b.evaluate(x), c.evaluate(x)};
        Eigen::Matrix3d j;
        for (int i = 0; i < 3; ++i) j.row(i) = f[i].gradient.transpose();
        const double scale = f[0].gradient.norm() * f[1].gradient.norm() * f[2].gradient.norm();
        // Two parallel gradients, or three in one plane (no single point).
        if (!(std::abs(j.determinant()) > kMinSine * scale)) return std::nullopt;
        const Vec3 step = j.partialPivLu().solve(Vec3(f[0].value, f[1].value, f[2].value));
        if (residual(f) <= tolerance && step.norm() <= tolerance) return x;
        x -= clamp_length(step, options.max_step * h);
    }
    return std::nullopt;
}

}  // namespace resharp
