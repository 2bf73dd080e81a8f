#include "resharp/surfaces/local_quadric.h"

namespace resharp {

Eigen::Matrix3d tangent_frame(const Vec3& n) {
    const Vec3 t1 = n.unitOrthogonal();
    Eigen::Matrix3d frame;
    frame << t1, n.cross(t1), n;
    return frame;
}

SurfaceValue LocalQuadric::evaluate(const Vec3& p) const {
    const Vec3 local = frame.transpose() * (p - origin);
    const double u = local.x(), v = local.y();
    const double a = curvature[0], b = curvature[1], c = curvature[2];
    const double height = 0.5 * (a * u * u + 2.0 * b * u * v + c * v * v);
    const Vec3 local_gradient(-(a * u + b * v), -(b * u + c * v), 1.0);
    return {local.z() - height, frame * local_gradient};
}

LocalQuadric quadric_from_normal_slope(const Vec3& origin, const Vec3& normal,
                                       const Eigen::Matrix3d& normal_slope) {
    // The height's normal is (-w_u, -w_v, 1) to first order, so its derivative along t_j has
    // component -w_ij along t_i: the curvatures are minus the slope seen in the tangent frame.
    const Eigen::Matrix3d frame = tangent_frame(normal);
    const Eigen::Matrix2d slope =
        frame.leftCols<2>().transpose() * normal_slope * frame.leftCols<2>();
    return {.origin = origin,
            .frame = frame,
            .curvature =
                Eigen::Vector3d(-slope(0, 0), -0.5 * (slope(0, 1) + slope(1, 0)), -slope(1, 1))};
}

}  // namespace resharp
