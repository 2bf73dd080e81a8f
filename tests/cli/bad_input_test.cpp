// The CLI contract for bad input: `resharp restore BAD -o OUT` exits 2, prints
// "resharp: error: <message naming the file and the place>" on stderr, and creates no output.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

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
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // Flat, as in restore_cli_test.cpp, so that nothing is left behind in the temporary
    // directory; a parameterised test's name holds a '/'.
    std::string name = info->name();
    std::replace(name.begin(), name.end(), '/', '_');
    const auto scratch = std::filesystem::temp_directory_path() /
                         ("resharp_cli_tests_" + std::to_string(::getpid()) + "_" + name);
    const auto out_dir = scratch / "out";
    std::filesystem::remove_all(scratch);
    std::filesystem::create_directories(out_dir);
    const auto input = test::bad_files_dir() / e.file;

    const CliRun run = run_restore(input, out_dir / "restored.stl", scratch / "stderr.txt");

    EXPECT_EQ(run.exit_code, 2) << run.stderr_text;
    const std::string expected_start = "resharp: error: " + input.string() + ": ";
    EXPECT_EQ(run.stderr_text.rfind(expected_start, 0), 0u) << run.stderr_text;
    if (e.kind == "parse") {
        EXPECT_NE(run.stderr_text.find(": " + e.location + ": "), std::string::npos)
            << run.stderr_text;
    }
    EXPECT_NE(run.stderr_text.find(e.reason), std::string::npos) << run.stderr_text;
    EXPECT_TRUE(std::filesystem::is_empty(out_dir)) << "output or temporary file left behind";
    std::filesystem::remove_all(scratch);
}

INSTANTIATE_TEST_SUITE_P(Manifest, BadInput, ::testing::ValuesIn(test::load_bad_file_manifest()),
                         [](const auto& row) { return test::test_name_for(row.param.file); });

}  // namespace
}  // namespace resharp::cli
