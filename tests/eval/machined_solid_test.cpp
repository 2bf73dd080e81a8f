#include "resharp/eval/machined_solid.h"

#include <gtest/gtest.h>

#include "milled_part.h"

namespace resharp::eval {
namespace {

using sim::Tool;
using sim::ToolShape;

const sim::Box3 kStock(Vec3(0, 0, 0), Vec3(30, 20, 10));

// A flat-end slot along x at y = 10, floor z = 5 (move 2), through the stock's -x face.
test::MilledPart slot() {
    return test::MilledPart(kStock, {{1, Tool::make(ToolShape::FlatEnd, 6, 0, 20)}},
                            "T1 M6\nG0 X-5 Y10 Z30\nG1 Z5\nX15\nG0 Z30\nM30\n");
}

TEST(MachinedSolid, CrossingsAreTheBoundaryNearThePoint) {
    const test::MilledPart part = slot();
    const auto floor = part.solid.crossings_near(Vec3(8, 10, 5.1), 2, 0.5);
    ASSERT_EQ(floor.size(), 1u);
    EXPECT_DOUBLE_EQ(floor[0].t, 5.0);
    EXPECT_EQ(floor[0].surface, sim::tool_surface_id(2, sim::ToolPart::Bottom));
    EXPECT_EQ(floor[0].normal, Vec3::UnitZ());

    const auto top = part.solid.crossings_near(Vec3(8, 2, 9.8), 2, 0.5);  // beside the slot
    ASSERT_EQ(top.size(), 1u);
    EXPECT_DOUBLE_EQ(top[0].t, 10.0);
    EXPECT_EQ(top[0].surface, 5);

    const auto wall = part.solid.crossings_near(Vec3(8, 12.8, 7), 1, 0.5);  // the slot's +y wall
    ASSERT_EQ(wall.size(), 1u);
    EXPECT_NEAR(wall[0].t, 13.0, 1e-12);
    EXPECT_EQ(wall[0].surface, sim::tool_surface_id(2, sim::ToolPart::Side));
    EXPECT_NEAR(wall[0].normal.y(), -1.0, 1e-12);

    EXPECT_TRUE(part.solid.crossings_near(Vec3(8, 10, 9.8), 2, 0.5).empty());  // inside the slot
    // Beyond the slot's end (x = 15 + 3) the top is untouched.
    EXPECT_EQ(part.solid.crossings_near(Vec3(19, 10, 10), 2, 0.5).size(), 1u);
}

TEST(MachinedSolid, SurfaceNearNamesTheStockAndTheTool) {
    const test::MilledPart part = slot();
    const auto top = part.solid.surface_near(5, Vec3(3, 3, 10));
    ASSERT_EQ(top.kind, MachinedSolid::SurfaceKind::Exact);
    EXPECT_EQ(top.distance, 0.0);
    const auto wall =
        part.solid.surface_near(sim::tool_surface_id(2, sim::ToolPart::Side), Vec3(8, 13.5, 7));
    ASSERT_EQ(wall.kind, MachinedSolid::SurfaceKind::Exact);
    EXPECT_NEAR(wall.distance, 0.5, 1e-12);
    // A flat end has no corner; move 1 (the plunge to Z5 at X-5) never reaches the stock.
    EXPECT_EQ(
        part.solid.surface_near(sim::tool_surface_id(2, sim::ToolPart::Corner), Vec3::Ones()).kind,
        MachinedSolid::SurfaceKind::Unknown);
    EXPECT_EQ(
        part.solid.surface_near(sim::tool_surface_id(1, sim::ToolPart::Side), Vec3::Ones()).kind,
        MachinedSolid::SurfaceKind::Unknown);
}

}  // namespace
}  // namespace resharp::eval
