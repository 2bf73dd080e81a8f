#include "resharp/restoration/clearance.h"

#include <gtest/gtest.h>

namespace resharp {
namespace {

constexpr double kTolerance = 1e-9;

IdTriangle triangle(Triangle id, Vec3 a, Vec3 b, Vec3 c) { return IdTriangle::make(id, a, b, c); }

TEST(TrianglesMeet, DisjointTrianglesMeetOnlyWhenOnePiercesTheOther) {
    const IdTriangle floor = triangle({0, 1, 2}, {0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    const IdTriangle piercing = triangle({3, 4, 5}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 1.5, 1});
    const IdTriangle above = triangle({3, 4, 5}, {0.5, 0.5, 0.1}, {0.5, 0.5, 1}, {1.5, 1.5, 1});
    EXPECT_TRUE(triangles_meet(floor, piercing, kTolerance));
    EXPECT_FALSE(triangles_meet(floor, above, kTolerance));
}

TEST(TrianglesMeet, AVertexOnAnotherTrianglesEdgeIsAMeeting) {
    // A T-junction: the point (1, 0, 0) lies on the floor's edge but is not its vertex.
    const IdTriangle floor = triangle({0, 1, 2}, {0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    const IdTriangle wall = triangle({3, 4, 5}, {1, 0, 0}, {1, -1, 1}, {1, -1, -1});
    EXPECT_TRUE(triangles_meet(floor, wall, kTolerance));
}

TEST(TrianglesMeet, FanNeighboursInOnePlaneMeetOnlyWhereTheirAnglesOverlap) {
    const Vec3 apex(0, 0, 0);
    const IdTriangle east = triangle({0, 1, 2}, apex, {1, 0, 0}, {1, 1, 0});
    const IdTriangle north = triangle({0, 3, 4}, apex, {0, 1, 0}, {-1, 1, 0});
    const IdTriangle across = triangle({0, 5, 6}, apex, {-1, 0, 0}, {-1, -1, 0});  // opposite sides
    const IdTriangle overlapping = triangle({0, 7, 8}, apex, {1, 0.5, 0}, {0, 1, 0});
    EXPECT_FALSE(triangles_meet(east, north, kTolerance));
    EXPECT_FALSE(triangles_meet(east, across, kTolerance));
    EXPECT_TRUE(triangles_meet(east, overlapping, kTolerance));
}

TEST(TrianglesMeet, TrianglesSharingAVertexMeetWhenAFarEdgeCrossesTheOther) {
    const Vec3 apex(0, 0, 0);
    const IdTriangle floor = triangle({0, 1, 2}, apex, {2, 0, 0}, {0, 2, 0});
    const IdTriangle through = triangle({0, 3, 4}, apex, {1, 1, -1}, {1, 1, 1});
    const IdTriangle beside = triangle({0, 3, 4}, apex, {-1, -1, -1}, {-1, -1, 1});
    EXPECT_TRUE(triangles_meet(floor, through, kTolerance));
    EXPECT_FALSE(triangles_meet(floor, beside, kTolerance));
}

TEST(TrianglesMeet, TrianglesSharingAnEdgeMeetOnlyWhenFoldedFlat) {
    const IdTriangle floor = triangle({0, 1, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const IdTriangle hinged = triangle({1, 0, 3}, {1, 0, 0}, {0, 0, 0}, {0.5, 0.5, 0.01});
    const IdTriangle folded = triangle({1, 0, 3}, {1, 0, 0}, {0, 0, 0}, {0.5, 0.5, 0});
    const IdTriangle unfolded = triangle({1, 0, 3}, {1, 0, 0}, {0, 0, 0}, {0.5, -0.5, 0});
    EXPECT_FALSE(triangles_meet(floor, hinged, kTolerance));
    EXPECT_TRUE(triangles_meet(floor, folded, kTolerance));
    EXPECT_FALSE(triangles_meet(floor, unfolded, kTolerance));
}

}  // namespace
}  // namespace resharp
