#include "resharp/surfaces/plane_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace resharp {
namespace {

/// Points of the cylinder y^2 + (z + r)^2 = r^2 (axis along x, top at z = 0) over a patch
/// `reach` wide around the origin, on a lattice of `step`.
std::vector<Vec3> cylinder_patch(double r, double reach, double step) {
    std::vector<Vec3> points;
    for (double x = -reach; x <= reach + 1e-9; x += step) {
        for (double y = -reach; y <= reach + 1e-9; y += step)
            points.emplace_back(x, y, std::sqrt(r * r - y * y) - r);
    }
    return points;
}

TEST(PlaneFit, FitsPointsOfAPlaneExactlyFacingTheGivenSide) {
    const Vec3 n = Vec3(1, -2, 3).normalized();
    const Vec3 t = n.unitOrthogonal(), s = n.cross(t);
    std::vector<Vec3> points;
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 4; ++j) points.push_back(Vec3(0.2, 1, -1) + i * t + 0.5 * j * s);
    }
    const std::optional<PlaneFit> fit = fit_plane(points, -n);
    ASSERT_TRUE(fit);
    EXPECT_TRUE(fit->plane.normal.isApprox(-n, 1e-12));
    EXPECT_NEAR(fit->rms_distance, 0.0, 1e-12);
    for (const Vec3& p : points) EXPECT_NEAR(fit->plane.signed_distance(p), 0.0, 1e-12);
}

TEST(PlaneFit, PointsOnALineGiveNoPlane) {
    const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
    EXPECT_FALSE(fit_plane(line, Vec3::UnitZ()));
}

// A wall x = 0 whose points near the floor z = 0 lie off it towards a concave corner, as
// OpenVDB leaves them there (up to a quarter of a unit over the lowest rows): the least-squares
// plane leans, the plane most of them lie on is the wall's, to rounding.
TEST(PlaneOfMost, FindsTheWallUnderPointsAMesherPutOffIt) {
    std::vector<Vec3> points;
    for (int i = 0; i < 6; ++i) {
        for (int k = 0; k < 8; ++k) {
            const double z = 0.2 + 0.5 * k;
            const double off = z < 1.0 ? 0.25 * (1.0 - z) : 0.0;  // the lowest two rows
            points.emplace_back(off, 0.5 * i, z);
        }
    }
    const std::optional<PlaneFit> first = fit_plane(points, Vec3::UnitX());
    ASSERT_TRUE(first);
    EXPECT_GT(first->rms_distance, 0.02);
    EXPECT_GT(std::abs(first->plane.normal.z()), 0.02);  // leans towards the corner
    std::vector<Vec3> scratch;
    const std::optional<PlaneFit> most =
        fit_plane_of_most(points, Vec3::UnitX(), *first, 1e-6, 6, scratch);
    ASSERT_TRUE(most);
    EXPECT_LT(most->rms_distance, 1e-9);
    EXPECT_TRUE(most->plane.normal.isApprox(Vec3::UnitX(), 1e-9));
    EXPECT_NEAR(most->plane.offset, 0.0, 1e-9);
}

// Points of a curved face lie on no plane, however many are dropped: cylinders of radius 10
// and 100 over 3 units either way (a lattice of pitch 0.5), which a plane leaves by 0.45 and
// 0.045 at the rim, against a bound of a thousandth of that pitch's double.
TEST(PlaneOfMost, FindsNoneOnACylinder) {
    for (const double r : {10.0, 100.0}) {
        const std::vector<Vec3> points = cylinder_patch(r, 3.0, 0.5);
        const std::optional<PlaneFit> first = fit_plane(points, Vec3::UnitZ());
        ASSERT_TRUE(first);
        std::vector<Vec3> scratch;
        EXPECT_FALSE(fit_plane_of_most(points, Vec3::UnitZ(), *first, 1e-3, 6, scratch)) << r;
    }
}

// Fewer than half the points on the plane: no plane of most.
TEST(PlaneOfMost, NeedsHalfThePointsOnThePlane) {
    std::vector<Vec3> points;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const double off =
                j < 5 ? 0.1 * (5 - j) * (1 + (i % 3)) : 0.0;  // five rows of eight off
            points.emplace_back(0.5 * i, 0.5 * j, off);
        }
    }
    const std::optional<PlaneFit> first = fit_plane(points, Vec3::UnitZ());
    ASSERT_TRUE(first);
    std::vector<Vec3> scratch;
    EXPECT_FALSE(fit_plane_of_most(points, Vec3::UnitZ(), *first, 1e-6, 6, scratch));
}

// Two parallel lines of points lie on a plane, however they were meant: no plane of most
// (three columns down a cylinder, two of them off the plane of the third and its neighbour).
TEST(PlaneOfMost, TwoLinesOfPointsAreNoFace) {
    std::vector<Vec3> points;
    for (int k = 0; k < 8; ++k) {
        points.emplace_back(0.0, 0.0, 0.5 * k);
        points.emplace_back(0.5, 0.1, 0.5 * k);
    }
    for (int k = 0; k < 4; ++k) points.emplace_back(1.0, 0.4, 0.5 * k);  // a third, shorter
    const std::optional<PlaneFit> first = fit_plane(points, Vec3(-0.2, 1, 0));
    ASSERT_TRUE(first);
    EXPECT_GT(first->rms_distance, 0.01);
    std::vector<Vec3> scratch;
    EXPECT_FALSE(fit_plane_of_most(points, Vec3(-0.2, 1, 0), *first, 1e-6, 6, scratch));
}

// fit_plane_trimmed() keeps the plane where the points kept lie on two lines: OpenVDB's bevel
// across a concave edge two rows wide is a plane all the same, its ends bent off it (round a
// pocket's rounded corners) left out.
TEST(PlaneOfMost, TrimmedKeepsTwoLinesAndLeavesTheBentEndsOut) {
    std::vector<Vec3> points;
    for (int k = 0; k < 10; ++k) {
        const double end = k < 2 ? 0.3 * (2 - k) : 0.0;  // the first two columns bend away
        points.emplace_back(0.5 * k, 0.0, end);
        points.emplace_back(0.5 * k, 0.35, 0.35 + end);
    }
    const std::optional<PlaneFit> first = fit_plane(points, Vec3(0, -1, 1));
    ASSERT_TRUE(first);
    EXPECT_GT(first->rms_distance, 0.05);
    std::vector<Vec3> kept;
    EXPECT_FALSE(fit_plane_of_most(points, Vec3(0, -1, 1), *first, 1e-3, 6, kept));
    const std::optional<PlaneFit> trimmed =
        fit_plane_trimmed(points, Vec3(0, -1, 1), *first, 1e-3, 6, kept);
    ASSERT_TRUE(trimmed);
    EXPECT_LT(trimmed->rms_distance, 1e-9);
    EXPECT_TRUE(trimmed->plane.normal.isApprox(Vec3(0, -1, 1).normalized(), 1e-9));
    EXPECT_GE(kept.size(), 14u);  // of 20: the two bent columns' four, and a round's slack
    EXPECT_TRUE(std::none_of(kept.begin(), kept.end(), [](const Vec3& x) { return x.x() < 0.75; }));
}

// A line of points and one beside it spread across their plane by almost nothing; a lattice
// by as much one way as the other.
TEST(InPlaneSpread, TellsALineAndAPointFromALattice) {
    std::vector<Vec3> line{{0, 0, 0},   {0.5, 0, 0}, {1, 0, 0},
                           {1.5, 0, 0}, {2, 0, 0},   {0.5, 0.4, 0}};
    const std::optional<PlaneFit> thin = fit_plane(line, Vec3::UnitZ());
    ASSERT_TRUE(thin);
    EXPECT_LT(in_plane_spread(line, *thin), 0.05);
    std::vector<Vec3> lattice;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) lattice.emplace_back(0.5 * i, 0.5 * j, 0.0);
    }
    const std::optional<PlaneFit> wide = fit_plane(lattice, Vec3::UnitZ());
    ASSERT_TRUE(wide);
    EXPECT_NEAR(in_plane_spread(lattice, *wide), 1.0, 1e-9);
}

// On a cylinder of radius 10 sampled 3 units either way, a plane leaves the surface by its sag
// (0.45 at the rim); the second-order height fit finds the surface over any point to the
// cylinder's fourth-order terms.
TEST(HeightQuadric, FindsACylinderWhereThePlaneMissesIt) {
    const double r = 10.0;
    const std::vector<Vec3> points = cylinder_patch(r, 3.0, 0.5);
    const std::optional<PlaneFit> plane = fit_plane(points, Vec3::UnitZ());
    ASSERT_TRUE(plane);
    EXPECT_GT(plane->rms_distance, 0.05);
    for (const double y : {0.0, 1.3, 2.8}) {
        const Vec3 on_surface(0.4, y, std::sqrt(r * r - y * y) - r);
        const Vec3 off = on_surface + Vec3(0.0, 0.05, 0.2);  // a vertex off the face
        const std::optional<HeightFit> fit = fit_height_quadric(points, plane->plane, off);
        ASSERT_TRUE(fit) << y;
        EXPECT_LT(fit->rms_distance, 0.01 * plane->rms_distance) << y;
        const double radial = std::hypot(fit->point.y(), fit->point.z() + r);
        EXPECT_NEAR(radial, r, 2e-3) << y;                      // on the cylinder
        EXPECT_LT((fit->point - on_surface).norm(), 0.1) << y;  // over the vertex
    }
}

// The fitted surface as an implicit function: zero on the cylinder to its fourth-order terms,
// over its gradient's length a distance to first order off it, its gradient along the cylinder's
// normal and the derivative of its value; and where it meets the plane y = 2 (surfaces/junction.h),
// the point of the true curve x, 2, sqrt(r^2 - 4) - r.
TEST(HeightQuadric, IsASurfaceThatMeetsOthersOnTheirTrueJunction) {
    const double r = 10.0;
    const std::vector<Vec3> points = cylinder_patch(r, 3.0, 0.5);
    const std::optional<PlaneFit> plane = fit_plane(points, Vec3::UnitZ());
    ASSERT_TRUE(plane);
    const std::optional<HeightFit> fit = fit_height_quadric(points, plane->plane, Vec3(0.3, 1, 0));
    ASSERT_TRUE(fit);
    for (const double y : {-2.0, 0.5, 2.5}) {
        const Vec3 on(0.7, y, std::sqrt(r * r - y * y) - r);
        const Vec3 normal = Vec3(0, on.y(), on.z() + r).normalized();
        EXPECT_NEAR(fit->evaluate(on).value, 0.0, 2e-3) << y;
        const SurfaceValue at = fit->evaluate(on);
        EXPECT_NEAR((fit->evaluate(on + 0.01 * normal).value - at.value) / at.gradient.norm(), 0.01,
                    1e-4)
            << y;
        EXPECT_GT(fit->evaluate(on).gradient.normalized().dot(normal), 0.9999) << y;
        const double step = 1e-6;
        for (int a = 0; a < 3; ++a) {
            const Vec3 d = step * Vec3::Unit(a);
            const double slope = (fit->evaluate(on + d).value - fit->evaluate(on - d).value) / 2;
            EXPECT_NEAR(slope / step, fit->evaluate(on).gradient[a], 1e-6) << y << " " << a;
        }
    }
    struct Wall {
        SurfaceValue evaluate(const Vec3& p) const { return {p.y() - 2.0, Vec3::UnitY()}; }
    };
    const std::optional<Vec3> meet =
        edge_junction(*fit, Wall{}, Vec3(0.5, 2.2, 0.3), Vec3(0.5, 2.2, 0.3), {.pitch = 0.5});
    ASSERT_TRUE(meet);
    EXPECT_TRUE(meet->isApprox(Vec3(0.5, 2.0, std::sqrt(r * r - 4.0) - r), 1e-3));
}

TEST(HeightQuadric, TooFewOrCollinearPointsGiveNone) {
    const Plane plane{Vec3::UnitZ(), 0.0};
    std::vector<Vec3> few = cylinder_patch(10.0, 0.5, 0.5);  // 9 points
    EXPECT_FALSE(fit_height_quadric(few, plane, Vec3::Zero()));
    std::vector<Vec3> line;
    for (int i = 0; i < 12; ++i) line.emplace_back(i, 0.0, 0.1 * i * i);
    EXPECT_FALSE(fit_height_quadric(line, plane, Vec3::Zero()));
}

}  // namespace
}  // namespace resharp
