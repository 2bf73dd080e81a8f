// `resharp restore` on many files: a folder of good, bad and non-mesh files, the summary in
// input order, the worst exit code, nothing written for a failed file, refused output folders,
// --recursive, extensions in any case, and the same bytes as the single-file form.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "cli_run.h"

namespace resharp::cli {
namespace {

namespace fs = std::filesystem;

class BatchCli : public CliTest {
protected:
    /// Makes `dir_/in`: two copies of the example (one with an upper-case extension), a broken
    /// STL, a text file, and a subfolder with one more copy.
    void SetUp() override {
        CliTest::SetUp();
        fs::create_directories(dir_ / "in" / "sub");
        fs::copy_file(example_mesh(), dir_ / "in" / "good.stl");
        fs::copy_file(example_mesh(), dir_ / "in" / "Upper.STL");
        fs::copy_file(example_mesh(), dir_ / "in" / "sub" / "deep.stl");
        std::ofstream(dir_ / "in" / "broken.stl") << "solid broken\n  facet normal 0 0 1\n";
        std::ofstream(dir_ / "in" / "notes.txt") << "not a mesh\n";
    }

    /// The names of every file under `folder`, relative to it.
    std::set<std::string> files_under(const std::string& folder) const {
        std::set<std::string> names;
        if (!fs::exists(dir_ / folder)) return names;
        for (const auto& entry : fs::recursive_directory_iterator(dir_ / folder)) {
            if (entry.is_regular_file())
                names.insert(entry.path().lexically_relative(dir_ / folder).string());
        }
        return names;
    }
    /// Where `text` starts in `haystack`, or npos (for order checks).
    static std::size_t at(const std::string& haystack, const std::string& text) {
        return haystack.find(text);
    }
};

TEST_F(BatchCli, FolderRestoresGoodFilesReportsTheBadOneAndExitsTwo) {
    const CliRun run = restore(path("in") + " -o " + path("out") + "/ --report " + path("rep"));
    EXPECT_EQ(run.exit_code, 2) << run.stderr_text;
    // Extensions match in any case; the text file is not a mesh; nothing for the broken file.
    EXPECT_EQ(files_under("out"), (std::set<std::string>{"Upper.STL", "good.stl"}));
    EXPECT_EQ(files_under("rep"), (std::set<std::string>{"Upper.json", "good.json"}));
    const auto report = nlohmann::json::parse(bytes_of(dir_ / "rep" / "good.json"));
    EXPECT_EQ(report["input"]["triangles"], 39748);
    // The table lists the files sorted by path, the failure with its reason and place.
    const std::string& text = run.stderr_text;
    const std::size_t upper = at(text, "Upper.STL"), broken = at(text, "broken.stl"),
                      good = at(text, "good.stl");
    ASSERT_NE(upper, std::string::npos) << text;
    ASSERT_NE(broken, std::string::npos) << text;
    ASSERT_NE(good, std::string::npos) << text;
    EXPECT_LT(upper, broken);
    EXPECT_LT(broken, good);
    EXPECT_NE(at(text, "failed (exit 2): " + (dir_ / "in" / "broken.stl").string() + ": line "),
              std::string::npos)
        << text;
    EXPECT_NE(at(text, "39748"), std::string::npos) << text;
    EXPECT_EQ(at(text, "notes.txt"), std::string::npos) << text;
    EXPECT_EQ(at(text, "deep.stl"), std::string::npos) << "descended without --recursive";
    EXPECT_NE(at(text, "3 files: 2 restored, 1 failed"), std::string::npos) << text;
    EXPECT_EQ(at(text, "\r"), std::string::npos) << "progress bar drawn on a file";
}

TEST_F(BatchCli, FilesKeepCommandLineOrderAndGiveTheSingleFileBytes) {
    const CliRun run = restore(path("in/good.stl") + " " + path("in/sub/deep.stl") + " " +
                               path("in/Upper.STL") + " -o " + path("out") + " --jobs 2");
    ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
    const std::string& text = run.stderr_text;
    EXPECT_LT(at(text, "good.stl"), at(text, "deep.stl"));
    EXPECT_LT(at(text, "deep.stl"), at(text, "Upper.STL"));
    EXPECT_EQ(files_under("out"), (std::set<std::string>{"Upper.STL", "deep.stl", "good.stl"}));

    ASSERT_EQ(restore(path("in/good.stl") + " -q -o " + path("single.stl")).exit_code, 0);
    EXPECT_EQ(bytes_of(dir_ / "out" / "deep.stl"), bytes_of(dir_ / "single.stl"));
}

TEST_F(BatchCli, RecursiveMirrorsSubfolders) {
    const CliRun run =
        restore(path("in") + " -o " + path("out") + " -r --segments " + path("seg") + " -j 1");
    EXPECT_EQ(run.exit_code, 2) << run.stderr_text;
    EXPECT_EQ(files_under("out"), (std::set<std::string>{"Upper.STL", "good.stl", "sub/deep.stl"}));
    EXPECT_EQ(files_under("seg"), (std::set<std::string>{"Upper.segments.ply", "good.segments.ply",
                                                         "sub/deep.segments.ply"}));
}

TEST_F(BatchCli, AllGoodExitsZero) {
    const CliRun run = restore(path("in/sub") + " -o " + path("out") + "/");
    EXPECT_EQ(run.exit_code, 0) << run.stderr_text;
    EXPECT_EQ(files_under("out"), (std::set<std::string>{"deep.stl"}));
}

TEST_F(BatchCli, ExitCodeIsTheWorstOfTheFiles) {
    // A folder where good.stl's output should go: it cannot be written (exit 3), the broken
    // file is bad input (exit 2), Upper.STL is restored.
    fs::create_directories(dir_ / "out" / "good.stl");
    const CliRun run = restore(path("in") + " -o " + path("out"));
    EXPECT_EQ(run.exit_code, 3) << run.stderr_text;
    EXPECT_NE(at(run.stderr_text, "failed (exit 3)"), std::string::npos) << run.stderr_text;
    EXPECT_NE(at(run.stderr_text, "failed (exit 2)"), std::string::npos) << run.stderr_text;
    EXPECT_EQ(files_under("out"), (std::set<std::string>{"Upper.STL"}));
}

TEST_F(BatchCli, RefusesAnOutputFolderEqualToTheInputFolder) {
    const std::set<std::string> before = files_under("in");
    for (const std::string& output : {path("in"), path("in") + "/", path("in/sub/..")}) {
        const CliRun run = restore(path("in") + " -o " + output);
        EXPECT_EQ(run.exit_code, 1) << output;
        EXPECT_NE(at(run.stderr_text, "is the input folder"), std::string::npos) << run.stderr_text;
    }
    // Inside the input folder is refused with --recursive only (the next run would take the
    // outputs for inputs).
    EXPECT_EQ(restore(path("in") + " -r -o " + path("in/restored")).exit_code, 1);
    // A file given by name whose output would replace it.
    EXPECT_EQ(restore(path("in/good.stl") + " -o " + path("in") + "/").exit_code, 1);
    EXPECT_EQ(files_under("in"), before);
}

TEST_F(BatchCli, RefusesTwoInputsWithOneOutput) {
    const CliRun run =
        restore(path("in/sub/deep.stl") + " " + path("in/sub/deep.stl") + " -o " + path("out"));
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(at(run.stderr_text, "would be written for"), std::string::npos) << run.stderr_text;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(BatchCli, FlagsOfTheOtherForm) {
    EXPECT_EQ(restore(path("in") + " -o " + path("out") + " --threads 2").exit_code, 1);
    const CliRun single = restore(path("in/good.stl") + " -o " + path("one.stl") + " --jobs 2");
    EXPECT_EQ(single.exit_code, 1);
    EXPECT_NE(at(single.stderr_text, "applies to a batch only"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "one.stl"));
}

TEST_F(BatchCli, AFolderWithoutMeshesIsBadInput) {
    fs::create_directories(dir_ / "empty");
    std::ofstream(dir_ / "empty" / "readme.txt") << "nothing here\n";
    const CliRun run = restore(path("empty") + " -o " + path("out"));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(at(run.stderr_text, "no .stl, .obj, .ply or .off file"), std::string::npos)
        << run.stderr_text;
}

TEST_F(BatchCli, ProgressBarOnATerminalOnly) {
    // script(1) gives the command a terminal; its transcript is what the terminal showed.
    const CliRun run =
        run_shell("script -qec " +
                      cli::quoted(std::string(RESHARP_CLI) + " restore " + (dir_ / "in").string() +
                                  " -o " + (dir_ / "out").string()) +
                      " " + path("tty.txt"),
                  dir_ / "stderr.txt");
    EXPECT_EQ(run.exit_code, 2);
    const std::string shown = bytes_of(dir_ / "tty.txt");
    EXPECT_NE(at(shown, "\rresharp: [##########"), std::string::npos) << shown;
    EXPECT_NE(at(shown, "3/3 files, 1 failed"), std::string::npos) << shown;
}

}  // namespace
}  // namespace resharp::cli
