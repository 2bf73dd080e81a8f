#pragma once
/// Where exact surfaces meet: the point of the curve where two implicit surfaces meet nearest a
/// segment (a crossing edge's ideal point), and the point where three meet (a corner's). Both
/// are found by bounded Newton iterations with a convergence check, never by sampling.

#include <optional>

#include "resharp/eval/exact_surface.h"

namespace resharp::eval {

struct JunctionSolverOptions {
    double pitch = 0.5;       ///< h, mm: the unit of the two lengths below
    int max_iterations = 60;  ///< bound on Newton steps; no convergence by then is a failure
    /// In h: converged when every surface's value over its gradient's length (a first-order
    /// distance from it) and the last step are below this.
    double tolerance = 1e-8;
    double max_step = 1.0;  ///< in h: longest single step
};

/// Takes two surfaces, a target point and a starting point; gives the point of the curve where
/// the surfaces meet nearest `target` (a local minimum of the distance, found from `start`), or
/// nothing if the iteration does not converge within its bound or the surfaces are parallel
/// there (no single curve). For two planes and the midpoint of a crossing edge as target this
/// is eq. 5.2's point: on both planes and on the plane through the target normal to their line.
std::optional<Vec3> edge_junction(const ImplicitSurface& a, const ImplicitSurface& b,
                                  const Vec3& target, const Vec3& start,
                                  const JunctionSolverOptions& options = {});

/// Takes three surfaces and a starting point; gives the point where all three meet nearest
/// `start` by Newton's method, or nothing if it does not converge within its bound or two of
/// the surfaces are parallel there.
std::optional<Vec3> corner_junction(const ImplicitSurface& a, const ImplicitSurface& b,
                                    const ImplicitSurface& c, const Vec3& start,
                                    const JunctionSolverOptions& options = {});

}  // namespace resharp::eval
