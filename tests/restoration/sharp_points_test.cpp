#include "resharp/restoration/sharp_points.h"

#include <gtest/gtest.h>

#include <cmath>

namespace resharp {
namespace {

// Section through a convex right-angle edge along z at the origin: top face y = 0 (x < 0),
// side face x = 0 (y < 0).
const Vec3 kTop(0, 1, 0);
const Vec3 kSide(1, 0, 0);

TEST(EdgePoint, LandsOnTheIdealEdgeOfAConvexRightAngle) {
    const Vec3 a(-0.3, 0.0, 0.7);
    const Vec3 b(0.0, -0.2, 0.9);
    const auto m = edge_point(a, kTop, b, kSide);
    ASSERT_TRUE(m.has_value());
    EXPECT_NEAR(m->x(), 0.0, 1e-15);
    EXPECT_NEAR(m->y(), 0.0, 1e-15);
    EXPECT_NEAR(m->z(), 0.8, 1e-15);  // the mid-plane of eq. 5.2
    EXPECT_TRUE(passes_flip_test(a, kTop, b, kSide));
    EXPECT_TRUE(passes_flip_test(b, kSide, a, kTop));  // symmetric in its two ends
}

TEST(EdgePoint, ConcaveEdgePassesTheFlipTestToo) {
    // L-block inner edge: floor y = 0 (x > 0), wall x = 0 (y > 0).
    const Vec3 a(0.3, 0.0, 0.0);
    const Vec3 b(0.0, 0.2, 0.0);
    const auto m = edge_point(a, kTop, b, kSide);
    ASSERT_TRUE(m.has_value());
    EXPECT_LT(m->norm(), 1e-15);
    EXPECT_TRUE(passes_flip_test(a, kTop, b, kSide));
}

TEST(EdgePoint, FlipTestRefusesAPointOutsideTheBand) {
    // a lies on the top plane but beyond the edge: the traces meet behind a, not between.
    const Vec3 a(0.3, 0.0, 0.0);
    const Vec3 b(0.0, -0.2, 0.0);
    EXPECT_FALSE(passes_flip_test(a, kTop, b, kSide));
}

TEST(EdgePoint, FlipTestRefusesAPointAtAnEndAtEveryScale) {
    // The traces meet within rounding of a (1e-14 of the band's width away): eq. 5.4's sign is
    // then rounding, so the point is refused at any scale; 1e-6 of the width is a real band.
    for (double s : {1e-3, 1.0, 25.4, 1e3}) {
        SCOPED_TRACE(s);
        const Vec3 b = s * Vec3(0.0, -0.2, 0.0);
        EXPECT_FALSE(passes_flip_test(s * Vec3(-2e-15, 0.0, 0.0), kTop, b, kSide));
        EXPECT_TRUE(passes_flip_test(s * Vec3(-2e-7, 0.0, 0.0), kTop, b, kSide));
    }
}

TEST(EdgePoint, ParallelNormalsGiveNoPoint) {
    const Vec3 a(0, 0, 0), b(1, 0, 0);
    EXPECT_FALSE(edge_point(a, kTop, b, kTop).has_value());
    EXPECT_FALSE(passes_flip_test(a, kTop, b, kTop));
}

TEST(EdgePoint, ObliqueDihedralAngle) {
    // Planes through the z-axis with normals 40 degrees apart.
    const double t = 40.0 * M_PI / 180.0;
    const Vec3 n1(0, 1, 0), n2(std::sin(t), std::cos(t), 0);
    const Vec3 a(-0.4, 0.0, 0.0);                               // on plane 1
    const Vec3 b = 0.3 * Vec3(std::cos(t), -std::sin(t), 0.0);  // on plane 2
    const auto m = edge_point(a, n1, b, n2);
    ASSERT_TRUE(m.has_value());
    EXPECT_LT(m->norm(), 1e-14);
    EXPECT_TRUE(passes_flip_test(a, n1, b, n2));
}

TEST(CornerPoint, MeetsThreePlanes) {
    const auto m = corner_point(Vec3(0.9, 2, 0.5), Vec3(0, 1, 0), Vec3(1, 0.3, 0.1), Vec3(1, 0, 0),
                                Vec3(0.2, 0.1, 3), Vec3(0, 0, 1));
    ASSERT_TRUE(m.has_value());
    EXPECT_TRUE(m->isApprox(Vec3(1, 2, 3), 1e-15));
    EXPECT_FALSE(corner_point(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(1, 0, 0),
                              Vec3(2, 0, 0), Vec3(1, 0, 0))
                     .has_value());
}

}  // namespace
}  // namespace resharp
