#include "resharp/sim/job.h"

#include <gtest/gtest.h>

#include <numbers>

#include "resharp/core/errors.h"

namespace resharp::sim {
namespace {

const char* kJob = R"({
  "stock": {"min": [0, 0, 0], "max": [100, 80, 30]},
  "pitch": 0.25,
  "program": "part.nc",
  "tools": [
    {"number": 1, "type": "flat", "diameter": 10, "flute_length": 25},
    {"number": 2, "type": "ball", "diameter": 6, "flute_length": 20},
    {"number": 5, "type": "bullnose", "diameter": 8, "corner_radius": 1, "flute_length": 20},
    {"number": 7, "type": "vbit", "diameter": 12, "tip_angle": 60, "tip_diameter": 0.5,
     "flute_length": 26}
  ],
  "mesher": "surface-nets",
  "seam_duplicates": 4
})";

TEST(Job, ReadsStockToolsPitchAndResolvesTheProgram) {
    const Job job = parse_job(kJob, "job.json", "/parts/mech");
    EXPECT_EQ(job.stock.max(), Vec3(100, 80, 30));
    EXPECT_EQ(job.pitch, 0.25);
    EXPECT_EQ(job.program, "/parts/mech/part.nc");
    EXPECT_EQ(job.start_position, Vec3(50, 40, 80));
    ASSERT_EQ(job.tools.size(), 4u);
    EXPECT_EQ(job.tools.at(2).shape, ToolShape::BallEnd);
    EXPECT_EQ(job.tools.at(2).corner_radius, 3.0);
    EXPECT_EQ(job.tools.at(5).corner_radius, 1.0);
    EXPECT_EQ(job.tools.at(7).shape, ToolShape::Cone);
    EXPECT_NEAR(job.tools.at(7).half_angle, std::numbers::pi / 6, 1e-15);
    EXPECT_EQ(job.tools.at(7).tip_radius, 0.25);
    EXPECT_EQ(job.meshing.mesher, Mesher::SurfaceNets);
    EXPECT_EQ(job.meshing.seam_duplicates, 4);
    const Job plain = parse_job(R"({"stock": {"min": [0,0,0], "max": [1,1,1]}, "program": "a.nc",
        "tools": [{"number": 1, "type": "flat", "diameter": 1, "flute_length": 2}]})",
                                "job.json", ".");
    EXPECT_EQ(plain.meshing.mesher, Mesher::MarchingCubes);
    EXPECT_EQ(plain.meshing.seam_duplicates, 0);
}

/// The message parse_job() gives for `text`, or "no error".
std::string job_error(const std::string& text) {
    try {
        parse_job(text, "job.json", ".");
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "no error";
}

/// kJob with the first `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
    std::string text = kJob;
    return text.replace(text.find(from), from.size(), to);
}

TEST(Job, RejectsBadMeshersAndConesNamingTheKey) {
    const struct {
        std::string from, to, expected;
    } cases[] = {
        {"\"surface-nets\"", "\"marching\"", "job.json: mesher: must be"},
        {"\"surface-nets\"", "3", "job.json: mesher: must be"},
        {"\"seam_duplicates\": 4", "\"seam_duplicates\": -1", "job.json: seam_duplicates:"},
        {"\"seam_duplicates\": 4", "\"seam_duplicates\": 1.5", "job.json: seam_duplicates:"},
        {"\"tip_angle\": 60", "\"tip_angle\": 180", "tools[3].tip_angle: must lie strictly"},
        {"\"tip_angle\": 60", "\"tip_angle\": 0", "tools[3].tip_angle: must lie strictly"},
        {"\"tip_angle\": 60,", "", "tools[3].tip_angle: missing"},
        {"\"tip_diameter\": 0.5", "\"tip_diameter\": -0.5", "tools[3].tip_diameter: must not"},
        {"\"tip_diameter\": 0.5", "\"tip_diameter\": 12", "tools[3]: tip diameter must lie"},
        {"\"diameter\": 12", "\"diameter\": -12", "tools[3].diameter: must be positive"},
        {"\"flute_length\": 26", "\"flute_length\": 5", "tools[3]: tool flute length is shorter"},
        {"\"type\": \"vbit\"", "\"type\": \"chamfer\"", "tools[3].type: must be"},
        {"\"type\": \"flat\", \"diameter\": 10,",
         "\"type\": \"flat\", \"tip_angle\": 90, \"diameter\": 10,",
         "tools[0].tip_angle: does not apply to a \"flat\" tool"},
    };
    for (const auto& c : cases) {
        const std::string message = job_error(edited(c.from, c.to));
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.to << ": " << message;
    }
}

TEST(Job, RejectsBadJsonWithTheLineAndBadValuesWithTheKey) {
    try {
        parse_job("{\n\"stock\": {\n,}\n}", "job.json", ".");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.location().value, 3u);
    }
    const auto message = [](std::string text) {
        try {
            parse_job(text, "job.json", ".");
        } catch (const InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string bad = kJob;
    EXPECT_NE(
        message(bad.replace(bad.find("\"pitch\""), 7, "\"pitsh\"")).find("pitsh: unknown key"),
        std::string::npos);
    bad = kJob;
    EXPECT_NE(message(bad.replace(bad.find("\"diameter\": 10"), 14, "\"diameter\": -1"))
                  .find("tools[0].diameter: must be positive"),
              std::string::npos);
    bad = kJob;
    EXPECT_NE(message(bad.replace(bad.find("\"corner_radius\": 1"), 18, "\"corner_radius\": 9"))
                  .find("tools[2]"),
              std::string::npos);
    EXPECT_NE(
        message(R"({"stock": {"min": [0,0,0], "max": [1,1,1]}, "tools": []})").find("program"),
        std::string::npos);
    EXPECT_THROW(read_job("/nonexistent/job.json"), ReadError);
}

}  // namespace
}  // namespace resharp::sim
