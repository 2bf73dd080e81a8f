#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "resharp/eval/exact_surface.h"
#include "resharp/restoration/sharp_points.h"
#include "resharp/surfaces/junction.h"

namespace resharp::eval {
namespace {

using Form = ImplicitSurface::Form;

ImplicitSurface plane(const Vec3& normal, double offset) {
    return {.form = Form::Plane, .normal = normal.normalized(), .offset = offset};
}

/// A tool plunged at (x, y): its side is the vertical cylinder of radius r around that line.
sim::ToolMotion plunge_at(double x, double y) {
    return {.start = Vec3(x, y, 0), .end = Vec3(x, y, 0)};
}

ImplicitSurface cylinder(double x, double y, double r) {
    return {.form = Form::Wall, .motion = plunge_at(x, y), .radius = r};
}

/// A ball of radius r centred at c: a ball end plunged with its tip at c - r z.
ImplicitSurface sphere(const Vec3& c, double r) {
    return {.form = Form::Toroidal,
            .motion = plunge_at(c.x(), c.y()),
            .radius = r,
            .inset = 0,
            .height = c.z()};
}

/// A horizontal ball-end pass along x at y, its ball centre at height zc.
ImplicitSurface ball_pass(double y, double zc, double r) {
    return {.form = Form::Toroidal,
            .motion = {.start = Vec3(-50, y, zc - r), .end = Vec3(50, y, zc - r)},
            .radius = r,
            .inset = 0,
            .height = zc};
}

const JunctionSolverOptions kOptions{.pitch = 0.5};
constexpr double kExact = 1e-8;  // mm; the solver converges to 1e-8 h = 5e-9 mm

TEST(JunctionSolver, PlaneAndCylinderMeetOnTheirCircle) {
    const auto x = edge_junction(plane(Vec3::UnitZ(), 2), cylinder(0, 0, 3), Vec3(4, 1, 2.5),
                                 Vec3(3.2, 0.9, 2.3), kOptions);
    ASSERT_TRUE(x);
    const Vec3 expected(3 * 4 / std::sqrt(17.0), 3 * 1 / std::sqrt(17.0), 2);
    EXPECT_LE((*x - expected).norm(), kExact) << x->transpose();
}

TEST(JunctionSolver, PlaneAndSphereMeetOnTheirCircle) {
    const auto x = edge_junction(plane(Vec3::UnitZ(), 4), sphere(Vec3(1, 1, 5), 2), Vec3(4, 1, 3),
                                 Vec3(2.6, 1.2, 4.1), kOptions);
    ASSERT_TRUE(x);
    EXPECT_LE((*x - Vec3(1 + std::sqrt(3.0), 1, 4)).norm(), kExact) << x->transpose();
}

// Two parallel ball-end passes 2 mm apart (R = 3) leave a cusp along x at y = 1, 2 sqrt(2) below
// the balls' centres; the upper branch of their intersection is never reached from below.
TEST(JunctionSolver, TwoBallPassesMeetOnTheCusp) {
    const auto x = edge_junction(ball_pass(0, 3, 3), ball_pass(2, 3, 3), Vec3(5, 0.8, 0.5),
                                 Vec3(5.1, 0.9, 0.3), kOptions);
    ASSERT_TRUE(x);
    EXPECT_LE((*x - Vec3(5, 1, 3 - 2 * std::sqrt(2.0))).norm(), kExact) << x->transpose();
}

// Two ball-end plunges (spheres of radius 3, centres 2 apart) meet on a circle of radius
// sqrt(8) in the plane halfway; the point nearest the target is along the target's direction.
TEST(JunctionSolver, TwoBallPlungesMeetOnTheirCircle) {
    const Vec3 target(1.2, 0.5, -1);
    const auto x = edge_junction(sphere(Vec3(0, 0, 3), 3), sphere(Vec3(2, 0, 3), 3), target,
                                 Vec3(1.1, 0.6, 0.4), kOptions);
    ASSERT_TRUE(x);
    const Vec3 centre(1, 0, 3);
    const Vec3 in_plane(0, target.y(), target.z() - centre.z());
    const Vec3 expected = centre + std::sqrt(8.0) * in_plane.normalized();
    EXPECT_LE((*x - expected).norm(), kExact) << x->transpose();
}

// Where both surfaces are planes the junction nearest the edge's midpoint is eq. 5.2's point.
TEST(JunctionSolver, PlanesGiveTheFirstOrderPoint) {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    for (int k = 0; k < 100; ++k) {
        const Vec3 a(c(random), c(random), c(random)), b(c(random), c(random), c(random));
        const Vec3 na = Vec3(c(random), c(random), c(random)).normalized();
        const Vec3 nb = Vec3(c(random), c(random), c(random)).normalized();
        if (std::abs(na.dot(nb)) > 0.9) continue;
        const std::optional<Vec3> first = edge_point(a, na, b, nb);
        ASSERT_TRUE(first);
        const auto x =
            edge_junction(plane(na, na.dot(a)), plane(nb, nb.dot(b)), 0.5 * (a + b), a, kOptions);
        ASSERT_TRUE(x);
        EXPECT_LE((*x - *first).norm(), 1e-9) << k;
    }
}

// The plane x = 0, the floor z = 5 and a wall of radius 3 around (1, 1) meet at (0, 1 - sqrt 8, 5)
// and at (0, 1 + sqrt 8, 5); Newton's method finds the one it starts near.
TEST(JunctionSolver, ThreeSurfacesMeetAtTheCorner) {
    const ImplicitSurface side = plane(-Vec3::UnitX(), 0), floor = plane(Vec3::UnitZ(), 5);
    const ImplicitSurface wall = cylinder(1, 1, 3);
    const auto low = corner_junction(side, floor, wall, Vec3(0.2, -1.5, 4.8), kOptions);
    ASSERT_TRUE(low);
    EXPECT_LE((*low - Vec3(0, 1 - std::sqrt(8.0), 5)).norm(), kExact) << low->transpose();
    const auto high = corner_junction(side, floor, wall, Vec3(0.3, 3.5, 5.4), kOptions);
    ASSERT_TRUE(high);
    EXPECT_LE((*high - Vec3(0, 1 + std::sqrt(8.0), 5)).norm(), kExact) << high->transpose();
}

TEST(JunctionSolver, ParallelSurfacesHaveNoJunction) {
    const ImplicitSurface a = plane(Vec3::UnitZ(), 1), b = plane(Vec3::UnitZ(), 2);
    EXPECT_FALSE(edge_junction(a, b, Vec3::Zero(), Vec3::Zero(), kOptions));
    EXPECT_FALSE(corner_junction(a, b, plane(Vec3::UnitX(), 0), Vec3::Zero(), kOptions));
    // A plane tangent to a cylinder along a line: the gradients are parallel on it.
    EXPECT_FALSE(edge_junction(plane(Vec3::UnitX(), 3), cylinder(0, 0, 3), Vec3(3, 0, 0),
                               Vec3(3, 0, 0), kOptions));
}

// The iteration bound holds: a start 12 h away needs more than three steps of at most 1 h.
TEST(JunctionSolver, GivesUpAtItsIterationBound) {
    const ImplicitSurface floor = plane(Vec3::UnitZ(), 2), wall = cylinder(0, 0, 3);
    JunctionSolverOptions few = kOptions;
    few.max_iterations = 3;
    EXPECT_FALSE(edge_junction(floor, wall, Vec3(4, 1, 2.5), Vec3(9, 1, 2), few));
    EXPECT_TRUE(edge_junction(floor, wall, Vec3(4, 1, 2.5), Vec3(9, 1, 2), kOptions));
}

}  // namespace
}  // namespace resharp::eval
