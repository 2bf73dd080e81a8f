#include "resharp/sim/csg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "mesh_checks.h"
#include "resharp/core/errors.h"
#include "resharp/sim/marching_cubes.h"

namespace resharp::sim {
namespace {

CsgNode shape(Shape s, Placement p = {}) {
    CsgNode n;
    n.shape = s;
    n.placement = p;
    return n;
}

CsgNode operation(CsgOp op, std::vector<CsgNode> operands, Placement p = {}) {
    CsgNode n;
    n.op = op;
    n.operands = std::move(operands);
    n.placement = p;
    return n;
}

Placement turn(const Vec3& axis, double degrees, const Vec3& shift = Vec3::Zero()) {
    return {
        Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis.normalized()).toRotationMatrix(),
        shift};
}

std::vector<Interval> along(const CsgSolid& s, const Vec3& o, const Vec3& d) {
    std::vector<Interval> out;
    s.intersect_line(o, d.normalized(), out);
    return out;
}

/// Every crossing lies on its surface with the surface's own outward normal.
void expect_crossings_on_surfaces(const CsgSolid& s, const Vec3& o, const Vec3& d) {
    for (const Interval& i : along(s, o, d)) {
        for (const Crossing& c : {i.enter, i.exit}) {
            ASSERT_GE(c.surface, 0);
            ASSERT_LT(c.surface, static_cast<int>(s.surfaces().size()));
            const CsgSurface& surface = s.surfaces()[c.surface];
            const Vec3 p = o + c.t * d.normalized();
            EXPECT_NEAR(surface.value(p), 0.0, 1e-9);
            EXPECT_NEAR((surface.normal(p) - c.normal).norm(), 0.0, 1e-9);
        }
        EXPECT_LT(i.enter.normal.dot(d), 0.0);  // entering against the outward normal
        EXPECT_GT(i.exit.normal.dot(d), 0.0);
    }
}

TEST(Csg, RotatedBoxGivesTheChordOfItsSlab) {
    const CsgSolid s(shape(BoxShape{Vec3(-1, -2, -3), Vec3(1, 2, 3)}, turn(Vec3(0, 0, 1), 30)));
    // Along the box's own x axis through its centre: length 2, through faces 0 and 1.
    const Vec3 x = turn(Vec3(0, 0, 1), 30).rotation.col(0);
    const auto i = along(s, -10 * x, x);
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t - i[0].enter.t, 2.0, 1e-12);
    EXPECT_EQ(i[0].enter.surface, 0);
    EXPECT_EQ(i[0].exit.surface, 1);
    EXPECT_NEAR((i[0].exit.normal - x).norm(), 0.0, 1e-12);
    expect_crossings_on_surfaces(s, Vec3(0.3, -5, 0.2), Vec3(0.1, 1, 0.05));
}

TEST(Csg, SlantedCylinderConeSphereAndTorusChords) {
    const Placement slant = {
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), Vec3(1, 1, 1)).toRotationMatrix(),
        Vec3(1, 2, 3)};
    const Vec3 axis = Vec3(1, 1, 1).normalized();
    const Vec3 across = axis.cross(Vec3::UnitX()).normalized();
    const CsgSolid cylinder(shape(ConeShape{10, 2, 2}, slant));
    // Across the axis at mid-height: a chord of 2r; along the axis: cap to cap.
    auto i = along(cylinder, slant.translation + 5 * axis - 10 * across, across);
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t - i[0].enter.t, 4.0, 1e-12);
    EXPECT_EQ(i[0].enter.surface, 0);
    i = along(cylinder, slant.translation - 3 * axis, axis);
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t - i[0].enter.t, 10.0, 1e-12);
    EXPECT_EQ(i[0].enter.surface, 1);
    EXPECT_EQ(i[0].exit.surface, 2);

    const CsgSolid cone(shape(ConeShape{10, 4, 1}, slant));  // radius 4 - 0.3 z
    i = along(cone, slant.translation + 5 * axis - 10 * across, across);
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t - i[0].enter.t, 2 * 2.5, 1e-12);
    expect_crossings_on_surfaces(cone, slant.translation - across, axis + 0.2 * across);

    const CsgSolid ball(shape(SphereShape{3}, slant));
    i = along(ball, slant.translation + Vec3(0, 1, -10), Vec3::UnitZ());
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t - i[0].enter.t, 2 * std::sqrt(8.0), 1e-12);

    const CsgSolid torus(shape(TorusShape{5, 1}, slant));
    // In the torus's plane through its centre: two pieces [R - r, R + r] on either side.
    i = along(torus, slant.translation - 10 * across, across);
    ASSERT_EQ(i.size(), 2u);
    EXPECT_NEAR(i[0].enter.t, 10 - 6, 1e-9);
    EXPECT_NEAR(i[0].exit.t, 10 - 4, 1e-9);
    EXPECT_NEAR(i[1].enter.t, 10 + 4, 1e-9);
    EXPECT_NEAR(i[1].exit.t, 10 + 6, 1e-9);
    // Parallel to the axis through the tube at 0.5 from its centre line: sqrt(1 - 0.25) each way.
    i = along(torus, slant.translation + 5.5 * across - 10 * axis, axis);
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t - i[0].enter.t, 2 * std::sqrt(0.75), 1e-9);
    expect_crossings_on_surfaces(torus, slant.translation + Vec3(0.3, -7, 0.1), Vec3(0.2, 1, 0.3));
}

TEST(Csg, DifferenceReversesTheCuttersNormalsAndIds) {
    // A plate with a through hole along z.
    const CsgSolid s(
        operation(CsgOp::Difference,
                  {shape(BoxShape{Vec3(0, 0, 0), Vec3(20, 10, 2)}),
                   shape(ConeShape{4, 3, 3}, {Eigen::Matrix3d::Identity(), Vec3(10, 5, -1)})}));
    ASSERT_EQ(s.surfaces().size(), 9u);
    EXPECT_EQ(s.surfaces()[6].orientation, -1.0);
    EXPECT_TRUE(along(s, Vec3(10, 5, -5), Vec3::UnitZ()).empty());
    const auto i = along(s, Vec3(-1, 5, 1), Vec3::UnitX());
    ASSERT_EQ(i.size(), 2u);
    EXPECT_NEAR(i[0].exit.t, 1 + 7.0, 1e-12);
    EXPECT_EQ(i[0].exit.surface, 6);
    EXPECT_NEAR((i[0].exit.normal - Vec3::UnitX()).norm(), 0.0, 1e-12);  // into the hole
    EXPECT_NEAR(i[1].enter.t, 1 + 13.0, 1e-12);
    expect_crossings_on_surfaces(s, Vec3(-1, 4, 0.5), Vec3(1, 0.1, 0.05));
    EXPECT_FALSE(s.contains(Vec3(10, 5, 1)));
    EXPECT_TRUE(s.contains(Vec3(2, 5, 1)));
}

TEST(Csg, CoincidentFacesOfAUnionCloseEvenWhenRotated) {
    // A boss standing exactly on a plate, then the whole turned off the axes: one interval.
    const CsgNode part =
        operation(CsgOp::Union,
                  {shape(BoxShape{Vec3(0, 0, 0), Vec3(10, 10, 2)}),
                   shape(ConeShape{3, 2, 2}, {Eigen::Matrix3d::Identity(), Vec3(5, 5, 2)})},
                  turn(Vec3(1, 2, 3), 37));
    const CsgSolid s(part);
    const Placement p = turn(Vec3(1, 2, 3), 37);
    const auto i = along(s, p.apply(Vec3(5, 5, -4)), p.rotation.col(2));
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t - i[0].enter.t, 5.0, 1e-9);
    EXPECT_EQ(i[0].enter.surface, 4);  // plate bottom
    EXPECT_EQ(i[0].exit.surface, 8);   // boss top
}

TEST(Csg, IntersectionWithAHalfSpaceCutsAChamfer) {
    // A unit cube with its +x/+z edge cut at 45 degrees, 0.25 from the edge along each face.
    const Vec3 n = Vec3(1, 0, 1).normalized();
    const CsgSolid s(
        operation(CsgOp::Intersection,
                  {shape(BoxShape{Vec3::Zero(), Vec3::Ones()}),
                   shape(HalfSpaceShape{},
                         {Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), n).toRotationMatrix(),
                          Vec3(1, 0, 0.75)})}));
    const auto i = along(s, Vec3(-1, 0.5, 0.9), Vec3::UnitX());
    ASSERT_EQ(i.size(), 1u);
    EXPECT_NEAR(i[0].exit.t, 1 + 0.85, 1e-12);
    EXPECT_EQ(i[0].exit.surface, 6);
    EXPECT_NEAR((i[0].exit.normal - n).norm(), 0.0, 1e-12);
    EXPECT_NEAR(s.bounds().max().x(), 1.0, 0.0);
}

TEST(Csg, HalfSpacesCutTheBoundingBox) {
    // The half-space z >= 1 (outward normal -z): a ball's cap with it, a cube's lower half
    // without it.
    const Placement above_one = {
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), -Vec3::UnitZ()).toRotationMatrix(),
        Vec3(0, 0, 1)};
    const CsgSolid cap(operation(CsgOp::Intersection,
                                 {shape(SphereShape{2}), shape(HalfSpaceShape{}, above_one)}));
    EXPECT_NEAR(cap.bounds().min().z(), 1.0, 1e-12);
    EXPECT_NEAR(cap.bounds().max().z(), 2.0, 1e-12);
    EXPECT_NEAR(cap.bounds().max().x(), 2.0, 1e-12);  // the cut box, not the cap's rim
    const CsgSolid half(operation(CsgOp::Difference, {shape(BoxShape{Vec3::Zero(), Vec3(2, 2, 2)}),
                                                      shape(HalfSpaceShape{}, above_one)}));
    EXPECT_NEAR(half.bounds().max().z(), 1.0, 1e-12);
    EXPECT_NEAR(half.bounds().max().x(), 2.0, 1e-12);
}

TEST(Csg, ContainsAgreesWithTheIntervals) {
    const CsgSolid s(operation(
        CsgOp::Difference,
        {operation(CsgOp::Union,
                   {shape(BoxShape{Vec3(-4, -4, -1), Vec3(4, 4, 1)}),
                    shape(SphereShape{2.5}, {Eigen::Matrix3d::Identity(), Vec3(0, 0, 1)})}),
         shape(TorusShape{3, 0.7}), shape(ConeShape{5, 1, 0.2}, turn(Vec3(1, 0, 0), 80))},
        turn(Vec3(2, -1, 1), 23)));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int line = 0; line < 200; ++line) {
        const Vec3 o(5 * u(random), 5 * u(random), 5 * u(random));
        const Vec3 d = Vec3(u(random), u(random), u(random)).normalized();
        const auto intervals = along(s, o - 20 * d, d);
        for (int k = 0; k < 50; ++k) {
            const double t = 20 + 10 * u(random);
            bool inside = false, near_end = false;
            for (const Interval& i : intervals) {
                inside |= t > i.enter.t && t < i.exit.t;
                near_end |= std::abs(t - i.enter.t) < 1e-9 || std::abs(t - i.exit.t) < 1e-9;
            }
            if (!near_end) {
                EXPECT_EQ(s.contains(o - 20 * d + t * d), inside) << line;
            }
        }
        expect_crossings_on_surfaces(s, o - 20 * d, d);
    }
}

TEST(Csg, MeshedPartIsClosedWithVerticesOnTheirSurfaces) {
    const CsgSolid s(
        operation(CsgOp::Difference,
                  {shape(BoxShape{Vec3(0, 0, 0), Vec3(12, 8, 3)}),
                   shape(ConeShape{5, 2, 2}, {Eigen::Matrix3d::Identity(), Vec3(4, 4, -1)}),
                   shape(TorusShape{2, 0.5}, {Eigen::Matrix3d::Identity(), Vec3(9, 4, 3)})},
                  turn(Vec3(1, 1, 0), 20)));
    // The bottom face passes through the origin, so the grid is shifted off it (as simulate
    // does by its grid phase): a face through grid nodes leaves degenerate faces.
    const GridSpec grid = grid_enclosing(s.bounds(), 0.2, Vec3::Constant(0.0828));
    const OracleMesh m = mesh_dexels(sample_solid(grid, s));
    EXPECT_EQ(m.stats.clamped_vertices, 0u);
    test::expect_clean_closed_outward(m.mesh);
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const CsgSurface& surface = s.surfaces()[m.surface_ids[v]];
        EXPECT_NEAR(surface.value(m.mesh.positions[v]), 0.0, 1e-9);
        EXPECT_NEAR((surface.normal(m.mesh.positions[v]) - m.normals[v]).norm(), 0.0, 1e-9);
    }
}

TEST(Csg, RejectsBadShapesEmptyAndUnboundedSolids) {
    EXPECT_THROW(CsgSolid(shape(BoxShape{Vec3::Zero(), Vec3(1, 0, 1)})), InvalidInput);
    EXPECT_THROW(CsgSolid(shape(ConeShape{1, 0, 0})), InvalidInput);
    EXPECT_THROW(CsgSolid(shape(TorusShape{1, 1})), InvalidInput);
    EXPECT_THROW(CsgSolid(shape(HalfSpaceShape{})), InvalidInput);
    EXPECT_THROW(CsgSolid(operation(CsgOp::Union, {})), InvalidInput);
    EXPECT_THROW(
        CsgSolid(operation(CsgOp::Intersection,
                           {shape(SphereShape{1}),
                            shape(SphereShape{1}, {Eigen::Matrix3d::Identity(), Vec3(5, 0, 0)})})),
        InvalidInput);
    Placement skew;
    skew.rotation(0, 1) = 0.5;
    EXPECT_THROW(CsgSolid(shape(SphereShape{1}, skew)), InvalidInput);
    CsgNode deep = shape(SphereShape{1});
    for (int k = 0; k < kMaxCsgDepth; ++k) deep = operation(CsgOp::Union, {deep});
    EXPECT_THROW(CsgSolid{deep}, InvalidInput);
}

}  // namespace
}  // namespace resharp::sim
