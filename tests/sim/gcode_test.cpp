#include "resharp/sim/gcode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "resharp/core/errors.h"

namespace resharp::sim {
namespace {

ToolPath parse(const std::string& text, const GcodeOptions& options = {}) {
    std::istringstream in(text);
    return parse_gcode(in, "test.nc", options);
}

/// The line number and message of the ParseError `text` raises.
std::pair<std::uint64_t, std::string> error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return {e.location().value, e.what()};
    }
    ADD_FAILURE() << "no error for: " << text;
    return {0, ""};
}

TEST(Gcode, LinesRapidsModalCoordinatesAndToolChange) {
    const ToolPath p = parse(
        "%\nO1000\nN10 G90 G21 G17 (safe start)\nT3 M6\nG0 X1 Y2 Z5 S12000 M3\n"
        "G1 Z-1 F300 ; plunge\nX4\nY6\nM30\n%\n");
    ASSERT_EQ(p.moves.size(), 4u);
    EXPECT_EQ(p.moves[0].kind, MoveKind::Rapid);
    EXPECT_EQ(p.moves[0].start, Vec3(0, 0, 0));
    EXPECT_EQ(p.moves[0].end, Vec3(1, 2, 5));
    EXPECT_EQ(p.moves[0].tool, 3);
    EXPECT_EQ(p.moves[0].line, 5u);
    EXPECT_EQ(p.moves[1].kind, MoveKind::Line);
    EXPECT_EQ(p.moves[1].end, Vec3(1, 2, -1));
    EXPECT_EQ(p.moves[2].end, Vec3(4, 2, -1));  // G1 is modal
    EXPECT_EQ(p.moves[3].end, Vec3(4, 6, -1));
}

TEST(Gcode, StartPositionInchesAndIncrementalMode) {
    const ToolPath p =
        parse("G20 G91 G1 X1 Y-1\nZ0.5\nG90 G21 X0\n", {.start_position = Vec3(10, 10, 10)});
    ASSERT_EQ(p.moves.size(), 3u);
    EXPECT_TRUE(p.moves[0].end.isApprox(Vec3(35.4, -15.4, 10), 1e-14));
    EXPECT_TRUE(p.moves[1].end.isApprox(Vec3(35.4, -15.4, 22.7), 1e-14));
    EXPECT_TRUE(p.moves[2].end.isApprox(Vec3(0, -15.4, 22.7), 1e-14));
}

TEST(Gcode, ArcsBothWaysWithCentreOffsetsAndRadius) {
    const ToolPath p =
        parse("G0 X5 Y0\nG3 X0 Y5 I-5 J0\nG2 X5 Y0 I0 J-5\nG3 X0 Y5 R5\nG2 X5 Y0 R-5\n");
    ASSERT_EQ(p.moves.size(), 5u);
    const double quarter = std::numbers::pi / 2;
    EXPECT_EQ(p.moves[1].kind, MoveKind::ArcCounterClockwise);
    EXPECT_NEAR(p.moves[1].sweep, quarter, 1e-12);
    EXPECT_NEAR(p.moves[1].radius, 5, 1e-12);
    EXPECT_EQ(p.moves[1].center, Eigen::Vector2d(0, 0));
    EXPECT_NEAR(p.moves[2].sweep, -quarter, 1e-12);
    EXPECT_NEAR((p.moves[3].center - Eigen::Vector2d(0, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR(p.moves[3].sweep, quarter, 1e-12);
    // R < 0: the long way round, centre on the far side of the chord.
    EXPECT_NEAR((p.moves[4].center - Eigen::Vector2d(5, 5)).norm(), 0, 1e-12);
    EXPECT_NEAR(p.moves[4].sweep, -3 * quarter, 1e-12);
}

TEST(Gcode, FullCircleAndHelix) {
    const ToolPath p = parse("G0 X5 Y0 Z0\nG2 I-5\nG3 X5 Y0 Z-2 I-5 J0\n");
    ASSERT_EQ(p.moves.size(), 3u);
    EXPECT_NEAR(p.moves[1].sweep, -2 * std::numbers::pi, 1e-12);
    EXPECT_NEAR(p.moves[2].sweep, 2 * std::numbers::pi, 1e-12);
    EXPECT_EQ(p.moves[2].end.z(), -2);
}

TEST(Gcode, ErrorsNameTheLine) {
    EXPECT_EQ(error_of("G0 X0\nG1 X1 Q5\n").first, 2u);
    EXPECT_NE(error_of("G0 X0\nG1 X1 Q5\n").second.find("unknown word 'Q5'"), std::string::npos);
    EXPECT_NE(error_of("G0 X5 Y0\nG3 X0 Y5.1 I-5 J0\n").second.find("radius mismatch"),
              std::string::npos);
    EXPECT_EQ(error_of("G0 X5 Y0\nG3 X0 Y5.1 I-5 J0\n").first, 2u);
    EXPECT_NE(error_of("G0 X0 Y0\nG2 X10 Y0 R4\n").second.find("smaller than half"),
              std::string::npos);
    EXPECT_EQ(error_of("G18\n").first, 1u);
    EXPECT_EQ(error_of("\n\nG1 X1 X2\n").first, 3u);
    EXPECT_EQ(error_of("X1\n").first, 1u);  // no motion mode yet
    EXPECT_EQ(error_of("M6\n").first, 1u);  // no tool selected
    EXPECT_EQ(error_of("G90.1\n").first, 1u);
    EXPECT_EQ(error_of("G1 X(open\n").first, 1u);
    EXPECT_EQ(error_of("G1 Xabc\n").first, 1u);
    EXPECT_EQ(error_of("G1 X1 I2\n").first, 1u);  // I on a line move
    EXPECT_EQ(error_of("M7\n").first, 1u);
    EXPECT_NE(error_of("G1 X1\nG5\n").second.find("test.nc: line 2"), std::string::npos);
}

TEST(Gcode, StopsAtProgramEndAndRejectsMissingFiles) {
    EXPECT_EQ(parse("G1 X1\nM30\nthis is not read\n").moves.size(), 1u);
    EXPECT_THROW(read_gcode("/nonexistent/program.nc"), ReadError);
}

}  // namespace
}  // namespace resharp::sim
