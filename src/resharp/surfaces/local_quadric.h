#pragma once
/// A smooth surface near one of its points, to second order: the height over its tangent plane,
/// w = (a u^2 + 2 b u v + c v^2) / 2 in the tangent frame (t1, t2, n) of its normal n there.
/// Planes have a = b = c = 0; a cylinder of radius r has curvature -1 / r across it (bending
/// away from n) and 0 along it; a sphere -1 / r every way. Two such surfaces, one per side of a
/// chamfer band, meet on the band's curved sharp edge (surfaces/junction.h), where their tangent
/// planes (eq. 5.2) meet off it by about r (1 - cos(s / r)) for a point s from the tangent points.

#include <Eigen/Core>

#include "resharp/core/types.h"
#include "resharp/surfaces/junction.h"

namespace resharp {

/// The tangent frame of unit normal n: columns t1, t2, n, orthonormal and right-handed. The same
/// n always gives the same frame, so curvatures stored per normal can be read back in it.
Eigen::Matrix3d tangent_frame(const Vec3& n);

struct LocalQuadric {
    Vec3 origin = Vec3::Zero();                           ///< the point the surface is about
    Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  ///< tangent_frame(n) at origin
    Eigen::Vector3d curvature = Eigen::Vector3d::Zero();  ///< a, b, c of the height, 1/mm

    /// w - height(u, v) at p, with its gradient: zero on the surface, positive on n's side, and
    /// a distance to first order near the origin.
    SurfaceValue evaluate(const Vec3& p) const;
};

/// The second-order surface through `origin` with unit normal `normal` there whose normal turns
/// by `normal_slope` * d for a tangent step d (#3x3: a normal field's derivative, as a linear
/// fit of face normals gives it; its normal component and its asymmetry are dropped).
LocalQuadric quadric_from_normal_slope(const Vec3& origin, const Vec3& normal,
                                       const Eigen::Matrix3d& normal_slope);

}  // namespace resharp
