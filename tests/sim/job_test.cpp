#include "resharp/sim/job.h"

#include <gtest/gtest.h>

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
    {"number": 5, "type": "bullnose", "diameter": 8, "corner_radius": 1, "flute_length": 20}
  ]
})";

TEST(Job, ReadsStockToolsPitchAndResolvesTheProgram) {
    const Job job = parse_job(kJob, "job.json", "/parts/mech");
    EXPECT_EQ(job.stock.max(), Vec3(100, 80, 30));
    EXPECT_EQ(job.pitch, 0.25);
    EXPECT_EQ(job.program, "/parts/mech/part.nc");
    EXPECT_EQ(job.start_position, Vec3(50, 40, 80));
    ASSERT_EQ(job.tools.size(), 3u);
    EXPECT_EQ(job.tools.at(2).shape, ToolShape::BallEnd);
    EXPECT_EQ(job.tools.at(2).corner_radius, 3.0);
    EXPECT_EQ(job.tools.at(5).corner_radius, 1.0);
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
