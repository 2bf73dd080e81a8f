// `resharp simulate` as a user runs it: the default mesher still writes the shipped example's
// bytes, and the oracle of a mesher that places vertices off the surface carries their nearest
// surface points.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_run.h"

namespace resharp::cli {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The header of a PLY file, up to and including "end_header".
std::string ply_header(const fs::path& file) {
    const std::string bytes = bytes_of(file);
    return bytes.substr(0, bytes.find("end_header"));
}

class SimulateCli : public ::testing::Test {
protected:
    CliRun simulate(const std::string& args) const {
        const fs::path job = fs::path(RESHARP_SOURCE_DIR) / "examples" / "bracket" / "job.json";
        return run_shell(std::string(RESHARP_CLI) + " simulate " + quoted(job) + " " + args,
                         scratch_.path() / "stderr.txt");
    }
    std::string path(const std::string& name) const { return quoted(scratch_.path() / name); }
    fs::path file(const std::string& name) const { return scratch_.path() / name; }

    ScratchDir scratch_{"resharp_simulate_cli"};
};

TEST_F(SimulateCli, DefaultMesherWritesTheShippedBracketByteForByte) {
    // examples/bracket.stl was made by `resharp simulate examples/bracket/job.json` before the
    // other meshers existed; mc, the default, must still give its bytes.
    const std::string shipped = bytes_of(fs::path(RESHARP_SOURCE_DIR) / "examples" / "bracket.stl");
    ASSERT_GT(shipped.size(), 84u);
    ASSERT_EQ(simulate("-q -o " + path("default.stl")).exit_code, 0);
    ASSERT_EQ(simulate("-q --mesher mc -o " + path("mc.stl")).exit_code, 0);
    EXPECT_EQ(bytes_of(file("default.stl")), shipped);
    EXPECT_EQ(bytes_of(file("mc.stl")), shipped);
}

TEST_F(SimulateCli, OffSurfaceMeshersWriteSurfacePointsInTheOracle) {
    ASSERT_EQ(simulate("-q -o " + path("mc.stl") + " --oracle " + path("mc.ply")).exit_code, 0);
    EXPECT_EQ(ply_header(file("mc.ply")).find("property double sx"), std::string::npos);
    for (const char* mesher : {"bisect", "midpoint", "surface-nets"}) {
        const CliRun run = simulate(std::string("-q --mesher ") + mesher + " -o " + path("m.stl") +
                                    " --oracle " + path("m.ply"));
        ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
        const std::string header = ply_header(file("m.ply"));
        EXPECT_NE(header.find("property int surface\nproperty double sx\nproperty double sy\n"
                              "property double sz\n"),
                  std::string::npos)
            << mesher << ":\n"
            << header;
        EXPECT_NE(bytes_of(file("m.stl")), bytes_of(file("mc.stl"))) << mesher;
    }
}

TEST_F(SimulateCli, SeamDuplicatesAreCountedInTheSummary) {
    const CliRun run =
        run_shell(std::string(RESHARP_CLI) + " simulate " +
                      quoted(fs::path(RESHARP_SOURCE_DIR) / "examples" / "bracket" / "job.json") +
                      " --seam-duplicates 3 -o " + path("s.stl"),
                  scratch_.path() / "stderr.txt");
    ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
    EXPECT_NE(run.stderr_text.find("duplicated on seams"), std::string::npos) << run.stderr_text;
    // 84-byte header and count, then 50 bytes a triangle: more than the 39,748 of the example.
    EXPECT_GT(fs::file_size(file("s.stl")), 84u + 50u * 39748u);
}

TEST_F(SimulateCli, UnknownMesherOnTheCommandLineIsAUsageError) {
    const CliRun run = simulate("-q --mesher voxels -o " + path("m.stl"));
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_FALSE(fs::exists(file("m.stl")));
}

}  // namespace
}  // namespace resharp::cli
