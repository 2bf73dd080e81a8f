#include "resharp/restoration/simple_fan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

/// `turns` full turns of `per_turn` triangles each around vertex 0 at the origin, the ring
/// vertices 1.. spiralling outwards and upwards (so that no two coincide), every triangle
/// counter-clockwise about +z and the last one closing the chain back to vertex 1.
struct TestFan {
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;
    std::vector<Vec3> normals;

    Fan fan() const {
        Fan f;
        for (std::size_t i = 0; i < triangles.size(); ++i) f.add(triangles[i], 0, normals[i]);
        return f;
    }
};

TestFan spiral(int per_turn, int turns, double rise) {
    TestFan t;
    t.positions.push_back(Vec3::Zero());
    const int ring = per_turn * turns;
    for (int i = 0; i < ring; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / per_turn + 0.1;
        const double radius = 1.0 + 0.01 * i;
        t.positions.emplace_back(radius * std::cos(angle), radius * std::sin(angle), rise * i);
    }
    for (int i = 0; i < ring; ++i) {
        const Index a = 1 + i, b = 1 + (i + 1) % ring;
        t.triangles.push_back({0, a, b});
    }
    for (const Triangle& tri : t.triangles) {
        t.normals.push_back(
            triangle_normal(t.positions[tri[0]], t.positions[tri[1]], t.positions[tri[2]]));
    }
    return t;
}

TEST(SimpleFan, AClosedFlatFanIsSimple) {
    const TestFan t = spiral(6, 1, 0.0);
    EXPECT_TRUE(is_simple_fan(t.positions, 0, t.fan()));
}

TEST(SimpleFan, AFanWindingTwiceIsNot) {
    // Every triangle faces +z and the chain closes, but it goes round twice: seen along the
    // axis, the second turn covers the first.
    const TestFan t = spiral(6, 2, 0.05);
    EXPECT_FALSE(is_simple_fan(t.positions, 0, t.fan()));
}

TEST(SimpleFan, AnOpenFanIsNot) {
    TestFan t = spiral(6, 1, 0.0);
    t.triangles.pop_back();
    t.normals.pop_back();
    EXPECT_FALSE(is_simple_fan(t.positions, 0, t.fan()));
}

TEST(SimpleFan, AFanWithAFaceTurnedOverIsNot) {
    TestFan t = spiral(6, 1, 0.0);
    std::swap(t.triangles[2][1], t.triangles[2][2]);  // that face now turns backwards
    t.normals[2] = -t.normals[2];
    EXPECT_FALSE(is_simple_fan(t.positions, 0, t.fan()));
}

TEST(SimpleFan, AFanWithAFaceTwiceIsNot) {
    TestFan t = spiral(6, 1, 0.0);
    t.triangles.push_back(t.triangles[0]);
    t.normals.push_back(t.normals[0]);
    EXPECT_FALSE(is_simple_fan(t.positions, 0, t.fan()));
}

TEST(SimpleFan, TooManyFacesAreLeftToThePairwiseTest) {
    const TestFan t = spiral(static_cast<int>(kMaxFan) + 1, 1, 0.0);
    EXPECT_TRUE(t.fan().overflow);
    EXPECT_FALSE(is_simple_fan(t.positions, 0, t.fan()));
    const TestFan most = spiral(static_cast<int>(kMaxFan), 1, 0.0);
    EXPECT_TRUE(is_simple_fan(most.positions, 0, most.fan()));
}

}  // namespace
}  // namespace resharp
