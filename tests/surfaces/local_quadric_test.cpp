#include "resharp/surfaces/local_quadric.h"

#include <gtest/gtest.h>

#include <cmath>

#include "resharp/restoration/sharp_points.h"
#include "resharp/surfaces/junction.h"

namespace resharp {
namespace {

/// The point of the vertical cylinder x^2 + y^2 = r^2 at angle phi and height z.
Vec3 on_cylinder(double r, double phi, double z) {
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// The slope of the cylinder's outward normal (x, y, 0) / r: it turns by 1 / r per unit of
/// tangent step across the axis, not at all along it.
Eigen::Matrix3d cylinder_slope(double r) { return Eigen::Vector3d(1 / r, 1 / r, 0).asDiagonal(); }

TEST(LocalQuadric, TangentFrameIsOrthonormalRightHandedAndRepeatable) {
    for (const Vec3& n :
         {Vec3(Vec3::UnitZ()), Vec3(Vec3(1, -2, 0.5).normalized()), Vec3(-Vec3::UnitX())}) {
        const Eigen::Matrix3d frame = tangent_frame(n);
        EXPECT_TRUE((frame.transpose() * frame).isIdentity(1e-15));
        EXPECT_NEAR(frame.determinant(), 1.0, 1e-15);
        EXPECT_EQ(frame.col(2), n);
        EXPECT_EQ(tangent_frame(n), frame);
    }
}

TEST(LocalQuadric, WithoutCurvatureItIsTheTangentPlane) {
    const Vec3 n = Vec3(1, 2, 3).normalized(), o(0.3, -1, 2);
    const LocalQuadric plane = quadric_from_normal_slope(o, n, Eigen::Matrix3d::Zero());
    EXPECT_EQ(plane.curvature, Eigen::Vector3d::Zero());
    const Vec3 p = o + 0.7 * n + 2.0 * n.unitOrthogonal();
    const SurfaceValue f = plane.evaluate(p);
    EXPECT_NEAR(f.value, 0.7, 1e-12);
    EXPECT_TRUE(f.gradient.isApprox(n, 1e-12));
}

TEST(LocalQuadric, CylinderBendsAwayFromItsNormalAcrossAndIsStraightAlong) {
    const double r = 5.0;
    const LocalQuadric q =
        quadric_from_normal_slope(on_cylinder(r, 0, 0), Vec3::UnitX(), cylinder_slope(r));
    // Points of the cylinder near the origin lie on the quadric to fourth order in their
    // distance (the height r - sqrt(r^2 - s^2) = s^2 / 2r + s^4 / 8r^3 ...).
    for (const Vec3& p :
         {on_cylinder(r, 0.1, 0.0), on_cylinder(r, -0.1, 0.4), on_cylinder(r, 0.05, -1.0)}) {
        const SurfaceValue f = q.evaluate(p);
        EXPECT_NEAR(f.value / f.gradient.norm(), 0.0, 2e-4) << p.transpose();
    }
    // Off the cylinder by 0.01 outwards, the value is that distance to first order.
    EXPECT_NEAR(q.evaluate(on_cylinder(r + 0.01, 0.05, 0.2)).value, 0.01, 1e-4);
}

TEST(LocalQuadric, DropsTheSlopesNormalPartAndAsymmetry) {
    const Vec3 n = Vec3::UnitZ();
    Eigen::Matrix3d slope = Eigen::Matrix3d::Zero();
    slope(2, 0) = 5.0;  // along n: no change of shape
    slope(0, 1) = 0.2;  // asymmetric: its symmetric half counts
    const LocalQuadric q = quadric_from_normal_slope(Vec3::Zero(), n, slope);
    const Eigen::Matrix3d frame = tangent_frame(n);
    const Eigen::Matrix2d tangent_slope =
        frame.leftCols<2>().transpose() * slope * frame.leftCols<2>();
    EXPECT_NEAR(q.curvature[1], -0.5 * (tangent_slope(0, 1) + tangent_slope(1, 0)), 1e-15);
    EXPECT_NEAR(q.curvature[0], -tangent_slope(0, 0), 1e-15);
    EXPECT_NEAR(q.curvature[2], -tangent_slope(1, 1), 1e-15);
}

// A boss of radius 3 (6 h at h = 0.5) standing up to z = 0: its top and its side meet on the
// circle x^2 + y^2 = 9. A chamfer band's crossing edge runs from a on the top to b on the side;
// its ideal point lies on the circle. The second-order surfaces meet on it; the tangent planes
// at a and b (eq. 5.2) meet off it.
TEST(LocalQuadric, SidesMeetOnTheCurvedEdgeWhereTangentPlanesMissIt) {
    const double r = 3.0, phi = 0.3;
    const Vec3 a(r - 0.4, 0, 0), b = on_cylinder(r, phi, -0.4);
    const Vec3 n_b(std::cos(phi), std::sin(phi), 0);
    const LocalQuadric top = quadric_from_normal_slope(a, Vec3::UnitZ(), Eigen::Matrix3d::Zero());
    const LocalQuadric side = quadric_from_normal_slope(b, n_b, cylinder_slope(r));

    const Vec3 target = 0.5 * (a + b);
    const auto first_order = edge_point(a, Vec3::UnitZ(), b, n_b);
    ASSERT_TRUE(first_order);
    const auto second_order =
        edge_junction(top, side, target, *first_order, {.pitch = (b - a).norm()});
    ASSERT_TRUE(second_order);
    const auto off_circle = [&](const Vec3& x) {
        return std::hypot(x.head<2>().norm() - r, x.z());
    };
    EXPECT_LT(off_circle(*second_order), 2e-4);
    EXPECT_GT(off_circle(*first_order), 2e-2);
}

}  // namespace
}  // namespace resharp
