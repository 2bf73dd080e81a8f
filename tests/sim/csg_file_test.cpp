#include "resharp/sim/csg_file.h"

#include <gtest/gtest.h>

#include <string>

#include "resharp/core/errors.h"

namespace resharp::sim {
namespace {

const char* kPlate = R"({
  // a plate with a hole, turned
  "description": "test part",
  "solid": {
    "difference": [
      {"box": {"min": [0, 0, 0], "max": [80, 50, 10]}},
      {"cylinder": {"from": [40, 25, -1], "to": [40, 25, 11], "radius": 8}}
    ],
    "rotate": {"axis": [0, 0, 1], "degrees": 90},
    "translate": [1, 2, 3]
  }
})";

/// The message parse_csg throws for `text`, or "no error".
std::string error_of(const std::string& text) {
    try {
        parse_csg(text, "part.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(CsgFile, ReadsTheTreeWithShapesPlacedAsTheFileSays) {
    const CsgNode root = parse_csg(kPlate, "part.json");
    ASSERT_EQ(root.op, CsgOp::Difference);
    ASSERT_EQ(root.operands.size(), 2u);
    const CsgSolid solid(root);
    // Turned 90 degrees about z, then moved: x from -50 + 1 to 1, y from 2 to 82.
    EXPECT_NEAR(solid.bounds().min().x(), -49.0, 1e-12);
    EXPECT_NEAR(solid.bounds().max().y(), 82.0, 1e-12);
    EXPECT_NEAR(solid.bounds().max().z(), 13.0, 1e-12);
    // The hole's axis lands at (-25 + 1, 40 + 2).
    EXPECT_FALSE(solid.contains(Vec3(-24, 42, 8)));
    EXPECT_TRUE(solid.contains(Vec3(-24, 42 + 9, 8)));
    const auto& cylinder = std::get<ConeShape>(root.operands[1].shape);
    EXPECT_DOUBLE_EQ(cylinder.length, 12.0);
    EXPECT_DOUBLE_EQ(cylinder.radius_top, 8.0);
}

TEST(CsgFile, ReadsEveryShape) {
    const CsgNode root = parse_csg(R"({"solid": {"union": [
        {"cone": {"from": [0, 0, 0], "to": [0, 0, 5], "radius_from": 3, "radius_to": 0}},
        {"sphere": {"center": [9, 0, 0], "radius": 2}},
        {"torus": {"center": [0, 9, 0], "axis": [1, 0, 0], "major": 3, "minor": 1}},
        {"intersection": [
            {"box": {"min": [20, 0, 0], "max": [22, 2, 2]}},
            {"halfspace": {"point": [21, 0, 0], "normal": [1, 0, 0]}}]}
    ]}})",
                                   "all.json");
    const CsgSolid solid(root);
    EXPECT_EQ(solid.surfaces().size(), 3u + 1 + 1 + 6 + 1);
    EXPECT_TRUE(solid.contains(Vec3(0, 0, 4.5)));   // near the cone's apex
    EXPECT_FALSE(solid.contains(Vec3(0, 9, 0)));    // the torus's hole
    EXPECT_TRUE(solid.contains(Vec3(0, 12, 0)));    // its tube (axis x: the ring in y, z)
    EXPECT_TRUE(solid.contains(Vec3(20.5, 1, 1)));  // the half box
    EXPECT_FALSE(solid.contains(Vec3(21.5, 1, 1)));
    EXPECT_NEAR(solid.bounds().max().x(), 21.0, 1e-12);  // the box cut by its half-space
}

TEST(CsgFile, ErrorsNameTheFileAndThePlace) {
    const auto expect_error = [](const std::string& text, const std::string& message) {
        const std::string e = error_of(text);
        EXPECT_EQ(e.rfind("part.json: ", 0), 0u) << e;
        EXPECT_NE(e.find(message), std::string::npos) << e;
    };
    expect_error(R"({"solid": {"box": {"min": [0, 0, 0], "max": [1, 1, 0]}}})",
                 "solid.box: a box needs min below max");
    expect_error(R"({"solid": {"union": [{"sphere": {"center": [0, 0, 0], "radius": -1}}]}})",
                 "solid.union[0].sphere: a sphere needs a positive radius");
    expect_error(R"({"solid": {"union": [{"sphere": {"center": [0, 0], "radius": 1}}]}})",
                 "solid.union[0].sphere.center: must be [x, y, z]");
    expect_error(R"({"solid": {"sphere": {"center": [0, 0, 0], "radius": 1}, "scale": 2}})",
                 "solid.scale: unknown key");
    expect_error(R"({"solid": {"sphere": {"center": [0, 0, 0], "radius": 1},
                              "box": {"min": [0, 0, 0], "max": [1, 1, 1]}}})",
                 "solid: has both");
    expect_error(R"({"solid": {"difference": []}})", "solid.difference: must be a non-empty");
    expect_error(R"({"solid": {"halfspace": {"point": [0, 0, 0], "normal": [0, 0, 1]}}})",
                 "solid: the solid is unbounded");
    expect_error(R"({"solid": {"cylinder": {"from": [1, 1, 1], "to": [1, 1, 1], "radius": 1}}})",
                 "solid.cylinder: from and to coincide");
    expect_error(R"({"solid": {"sphere": {"center": [0, 0, 0], "radius": 1},
                              "rotate": {"axis": [0, 0, 0], "degrees": 5}}})",
                 "solid.rotate.axis: must not be zero");
    expect_error(R"({"solid": {"torus": {"center": [0, 0, 0], "axis": [0, 0, 1], "major": 1,
                                        "minor": 2}}})",
                 "solid.torus: a torus needs major > minor > 0");
    expect_error(R"({"shape": {}})", "shape: unknown key");
    expect_error(R"({"description": "no solid"})", "solid: missing");
    std::string deep = R"({"sphere": {"center": [0, 0, 0], "radius": 1}})";
    for (int k = 0; k < kMaxCsgDepth; ++k) deep = R"({"union": [)" + deep + "]}";
    expect_error(R"({"solid": )" + deep + "}", "nested deeper than 64");
}

TEST(CsgFile, MalformedJsonGivesTheLine) {
    try {
        parse_csg("{\n\"solid\": {\n  \"box\": {,}\n}\n}", "part.json");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.location().value, 3u);
    }
    EXPECT_THROW(read_csg("/nonexistent/part.json"), ReadError);
}

}  // namespace
}  // namespace resharp::sim
