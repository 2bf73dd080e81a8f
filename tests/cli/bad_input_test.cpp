// The CLI contract for bad input: `resharp restore BAD -o OUT` and `resharp simulate BAD_JOB`
// exit 2, print "resharp: error: <message naming the file and the place>" on stderr, and create
// no output.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "io/bad_file_manifest.h"

namespace resharp::cli {
namespace {

using test::BadFileExpectation;

CliRun run_restore(const std::filesystem::path& input, const std::filesystem::path& output,
                   const std::filesystem::path& stderr_file) {
    return run_shell(
        std::string(RESHARP_CLI) + " restore " + quoted(input) + " -o " + quoted(output),
        stderr_file);
}

class BadInput : public ::testing::TestWithParam<BadFileExpectation> {};

TEST_P(BadInput, ExitsTwoNamingFileAndPlaceAndWritesNothing) {
    const BadFileExpectation& e = GetParam();
    const ScratchDir scratch("resharp_cli_tests");
    const auto out_dir = scratch.path() / "out";
    std::filesystem::create_directories(out_dir);
    const auto input = test::bad_files_dir() / e.file;

    const CliRun run = run_restore(input, out_dir / "restored.stl", scratch.path() / "stderr.txt");

    EXPECT_EQ(run.exit_code, 2) << run.stderr_text;
    const std::string expected_start = "resharp: error: " + input.string() + ": ";
    EXPECT_EQ(run.stderr_text.rfind(expected_start, 0), 0u) << run.stderr_text;
    if (e.kind == "parse") {
        EXPECT_NE(run.stderr_text.find(": " + e.location + ": "), std::string::npos)
            << run.stderr_text;
    }
    EXPECT_NE(run.stderr_text.find(e.reason), std::string::npos) << run.stderr_text;
    EXPECT_TRUE(std::filesystem::is_empty(out_dir)) << "output or temporary file left behind";
}

INSTANTIATE_TEST_SUITE_P(Manifest, BadInput, ::testing::ValuesIn(test::load_bad_file_manifest()),
                         [](const auto& row) { return test::test_name_for(row.param.file); });

/// A job file for `resharp simulate` with one thing wrong, and the place its message names.
struct BadJob {
    std::string name;
    std::string job;       ///< the job's JSON; its program is "p.nc"
    std::string program;   ///< the G-code
    bool names_program;    ///< the message names the program, not the job
    std::string expected;  ///< part of what follows "FILE: " in the message
};

const std::string kProgram = "T1 M6\nG0 X5 Y5 Z30\nG1 Z8\nX15\nG0 Z30\nM30\n";

/// A job over a small stock with one tool entry and `extra` top-level keys.
std::string job_with(const std::string& tool, const std::string& extra = "") {
    return R"({"stock": {"min": [0, 0, 0], "max": [20, 10, 10]}, "program": "p.nc", "tools": [)" +
           tool + "]" + extra + "}";
}

/// A V-bit entry with `keys` added.
std::string vbit(const std::string& keys) {
    return R"({"number": 1, "type": "vbit", "flute_length": 20, )" + keys + "}";
}

const std::string kVbit = vbit(R"("diameter": 6, "tip_angle": 90)");

std::vector<BadJob> bad_jobs() {
    return {
        {"unknown_mesher", job_with(kVbit, R"(, "mesher": "dual-contouring")"), kProgram, false,
         R"(mesher: must be "mc", "bisect", "midpoint" or "surface-nets")"},
        {"unknown_tool_type",
         job_with(R"({"number": 1, "type": "cone", "diameter": 6, "flute_length": 20})"), kProgram,
         false, "tools[0].type: must be"},
        {"tip_angle_180", job_with(vbit(R"("diameter": 6, "tip_angle": 180)")), kProgram, false,
         "tools[0].tip_angle: must lie strictly between 0 and 180 degrees"},
        {"tip_angle_zero", job_with(vbit(R"("diameter": 6, "tip_angle": 0)")), kProgram, false,
         "tools[0].tip_angle: must lie strictly between 0 and 180 degrees"},
        {"negative_diameter", job_with(vbit(R"("diameter": -6, "tip_angle": 90)")), kProgram, false,
         "tools[0].diameter: must be positive"},
        {"tip_wider_than_tool",
         job_with(vbit(R"("diameter": 6, "tip_angle": 90, "tip_diameter": 7)")), kProgram, false,
         "tools[0]: tip diameter must lie in [0, diameter)"},
        {"tip_angle_on_flat",
         job_with(
             R"({"number": 1, "type": "flat", "diameter": 6, "tip_angle": 90, "flute_length": 20})"),
         kProgram, false, R"(tools[0].tip_angle: does not apply to a "flat" tool)"},
        {"seams_beyond_the_grid", job_with(kVbit, R"(, "seam_duplicates": 500)"), kProgram, false,
         "seam_duplicates: seam duplicates must lie in 0.."},
        {"tool_missing_from_the_table", job_with(kVbit), "G0 Z30\nT9 M6\nG1 X5\n", true,
         "line 3: uses tool T9, which the tool table lacks"},
    };
}

class BadJobInput : public ::testing::TestWithParam<BadJob> {};

TEST_P(BadJobInput, ExitsTwoWithOneLineNamingFileAndPlaceAndWritesNothing) {
    const BadJob& b = GetParam();
    const ScratchDir scratch("resharp_cli_tests");
    const auto out_dir = scratch.path() / "out";
    std::filesystem::create_directories(out_dir);
    const auto job = scratch.path() / "job.json", program = scratch.path() / "p.nc";
    std::ofstream(job) << b.job;
    std::ofstream(program) << b.program;

    const CliRun run =
        run_shell(std::string(RESHARP_CLI) + " simulate " + quoted(job) + " -o " +
                      quoted(out_dir / "m.stl") + " --oracle " + quoted(out_dir / "o.ply") + " -q",
                  scratch.path() / "stderr.txt");

    EXPECT_EQ(run.exit_code, 2) << run.stderr_text;
    const auto& named = b.names_program ? program : job;
    EXPECT_EQ(run.stderr_text.rfind("resharp: error: " + named.string() + ": ", 0), 0u)
        << run.stderr_text;
    EXPECT_NE(run.stderr_text.find(b.expected), std::string::npos) << run.stderr_text;
    EXPECT_EQ(std::count(run.stderr_text.begin(), run.stderr_text.end(), '\n'), 1)
        << run.stderr_text;
    EXPECT_TRUE(std::filesystem::is_empty(out_dir)) << "output or temporary file left behind";
}

INSTANTIATE_TEST_SUITE_P(Jobs, BadJobInput, ::testing::ValuesIn(bad_jobs()),
                         [](const auto& row) { return row.param.name; });

}  // namespace
}  // namespace resharp::cli
