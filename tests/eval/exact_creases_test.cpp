#include "resharp/eval/exact_creases.h"

#include <gtest/gtest.h>

#include <numbers>

namespace resharp::eval {
namespace {

using sim::CsgNode;
using sim::CsgOp;

CsgNode shape(sim::Shape s, const Vec3& at = Vec3::Zero()) {
    CsgNode n;
    n.shape = s;
    n.placement.translation = at;
    return n;
}

CsgNode operation(CsgOp op, std::vector<CsgNode> operands) {
    CsgNode n;
    n.op = op;
    n.operands = std::move(operands);
    return n;
}

/// `node` turned about a slanted axis, off every grid plane.
CsgNode turned(CsgNode node) {
    node.placement =
        sim::Placement{Eigen::AngleAxisd(0.61, Vec3(1, 2, 3).normalized()).toRotationMatrix(),
                       Vec3::Zero()} *
        node.placement;
    return node;
}

CurveSamples creases_of(const CsgNode& node, double pitch) {
    const sim::CsgSolid solid(node);
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), pitch, 0.4142), solid);
    return sample_exact_creases(solid, grid);
}

/// Every sample lies on the curve where two of the solid's surfaces meet.
void expect_on_two_surfaces(const CsgNode& node, const CurveSamples& c) {
    const sim::CsgSolid solid(node);
    for (const Vec3& p : c.points) {
        int on = 0;
        for (const sim::CsgSurface& s : solid.surfaces()) on += std::abs(s.value(p)) < 1e-9;
        EXPECT_GE(on, 2) << p.transpose();
    }
}

TEST(ExactCreases, CubeEdgesSumToTwelveSides) {
    const CsgNode cube = shape(sim::BoxShape{Vec3::Zero(), Vec3::Constant(10)});
    for (const CsgNode& node : {cube, turned(cube)}) {
        const CurveSamples c = creases_of(node, 0.1);
        // Within about a pitch per edge end.
        EXPECT_NEAR(c.total_length(), 120.0, 24 * 0.1);
        expect_on_two_surfaces(node, c);
        for (const Vec3& t : c.tangents) EXPECT_NEAR(t.norm(), 1.0, 1e-12);
    }
}

TEST(ExactCreases, CylinderHasItsTwoRimCircles) {
    const CsgNode cylinder = shape(sim::ConeShape{6, 4, 4});
    for (const CsgNode& node : {cylinder, turned(cylinder)}) {
        const CurveSamples c = creases_of(node, 0.05);
        EXPECT_NEAR(c.total_length(), 2 * 2 * std::numbers::pi * 4, 0.01 * 16 * std::numbers::pi);
        expect_on_two_surfaces(node, c);
    }
}

TEST(ExactCreases, SmoothSolidsHaveNone) {
    // A ball, a ring torus, and a capsule (a cylinder capped by balls: tangent joins).
    const CsgNode capsule =
        operation(CsgOp::Union, {shape(sim::ConeShape{8, 2, 2}), shape(sim::SphereShape{2}),
                                 shape(sim::SphereShape{2}, Vec3(0, 0, 8))});
    for (const CsgNode& node :
         {shape(sim::SphereShape{5}), turned(shape(sim::TorusShape{5, 1.5})), turned(capsule)}) {
        EXPECT_EQ(creases_of(node, 0.1).size(), 0u);
    }
}

TEST(ExactCreases, ConcaveEdgesCountAndFacesInsideTheMaterialDoNot) {
    // An L of two overlapping boxes: [0,10]x[0,4]x[0,3] and [0,4]x[0,10]x[0,3]. Its outline in
    // plan has 6 corners (one concave) and perimeter 40; creases: the outline top and bottom
    // (80) and the six vertical edges (18). The boxes' faces inside the material add nothing.
    const CsgNode l = operation(CsgOp::Union, {shape(sim::BoxShape{Vec3::Zero(), Vec3(10, 4, 3)}),
                                               shape(sim::BoxShape{Vec3::Zero(), Vec3(4, 10, 3)})});
    for (const CsgNode& node : {l, turned(l)}) {
        const CurveSamples c = creases_of(node, 0.05);
        EXPECT_NEAR(c.total_length(), 98.0, 0.01 * 98);
    }
}

TEST(ExactCreases, PlateWithAHoleHasTheBoxEdgesAndTwoCircles) {
    const CsgNode plate =
        operation(CsgOp::Difference, {shape(sim::BoxShape{Vec3::Zero(), Vec3(20, 12, 4)}),
                                      shape(sim::ConeShape{6, 3, 3}, Vec3(10, 6, -1))});
    const double expected = 4 * (20 + 12 + 4) + 2 * 2 * std::numbers::pi * 3;
    const CurveSamples c = creases_of(turned(plate), 0.05);
    EXPECT_NEAR(c.total_length(), expected, 0.01 * expected);
    expect_on_two_surfaces(turned(plate), c);
}

}  // namespace
}  // namespace resharp::eval
