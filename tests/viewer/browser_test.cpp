// The viewer as a person sees it: pages written by `resharp restore --html` and `resharp view`,
// opened in headless Chromium with software WebGL by check_page.mjs, which reports console
// errors, requests that left the machine, and the pixels of each half of the canvas. Also that
// check_page.mjs itself catches what it should (a check that cannot fail proves nothing).

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_run.h"

namespace resharp::cli {
namespace {

namespace fs = std::filesystem;

class ViewerInBrowser : public CliTest {
protected:
    /// Runs check_page.mjs on `page` and gives its exit code and JSON report.
    std::pair<int, nlohmann::json> check(const std::string& page,
                                         const std::string& extra = "") const {
        const std::string command =
            std::string(RESHARP_NODE) + " " +
            quoted(fs::path(RESHARP_SOURCE_DIR) / "tests" / "viewer" / "check_page.mjs") +
            " --chromium " + RESHARP_CHROMIUM + " --page " + path(page) + " " + extra + " >" +
            path("report.json");
        const CliRun run = run_shell(command, dir_ / "driver.txt");
        nlohmann::json report = nlohmann::json::parse(bytes_of(dir_ / "report.json"), nullptr,
                                                      /*allow_exceptions=*/false);
        return {run.exit_code, report};
    }
    static const nlohmann::json& half(const nlohmann::json& report, int shot, int side) {
        return report["shots"][shot]["halves"][side];
    }
};

TEST_F(ViewerInBrowser, RestoredPageShowsBothMeshesWithoutErrors) {
    const CliRun run = restore(quoted(example_mesh()) + " -q -o " + path("out.stl") + " --html " +
                               path("page.html") + " --report " + path("r.json"));
    ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
    const auto [code, report] = check("page.html");
    ASSERT_EQ(code, 0) << report.dump(2);
    EXPECT_EQ(report["status"], "rendered");
    EXPECT_TRUE(report["errors"].empty());
    EXPECT_TRUE(report["outside_requests"].empty()) << "the page must open with no network";
    for (int side = 0; side < 2; ++side) {
        // A shaded part, not a blank or flat canvas: a third of the half is drawn, in hundreds
        // of shades (flat-shaded faces at many angles, the holes' walls).
        EXPECT_GT(half(report, 0, side)["distinct_colors"].get<int>(), 200) << side;
        EXPECT_GT(half(report, 0, side)["drawn_fraction"].get<double>(), 0.15) << side;
    }
    const auto numbers = nlohmann::json::parse(bytes_of(dir_ / "r.json"));
    EXPECT_EQ(report["viewer"]["inputTriangles"], numbers["input"]["triangles"]);
    EXPECT_EQ(report["viewer"]["restoredTriangles"], numbers["output"]["triangles"]);
    // Each inserted edge point lies on a drawn chain: at least one segment per two points.
    EXPECT_GT(report["viewer"]["sharpSegments"].get<int>(),
              numbers["restoration"]["edge_points_inserted"].get<int>() / 2);
}

TEST_F(ViewerInBrowser, TogglesShowAndHideEachLayer) {
    ASSERT_EQ(restore(quoted(example_mesh()) + " -q -o " + path("out.ply") + " --segments " +
                      path("seg.ply"))
                  .exit_code,
              0);
    const CliRun view = resharp("view " + quoted(example_mesh()) + " " + path("out.ply") +
                                " --segments " + path("seg.ply") + " -o " + path("page.html"));
    ASSERT_EQ(view.exit_code, 0) << view.stderr_text;
    const auto [code, report] =
        check("page.html", "--shots ';show-bands,show-sharp;show-patches;show-wireframe'");
    ASSERT_EQ(code, 0) << report.dump(2);
    ASSERT_EQ(report["shots"].size(), 4u);
    auto colored = [&](int shot, int side) {
        return half(report, shot, side)["colored_pixels"].get<int>();
    };
    // At first: yellow and magenta bands on the input, blue sharp edges on the restored mesh.
    EXPECT_GT(colored(0, 0), 2000);
    EXPECT_GT(colored(0, 1), 1000);
    // Both off: grey parts.
    EXPECT_LT(colored(1, 0), 50);
    EXPECT_LT(colored(1, 1), 50);
    // Patches on: the input's faces in their patch colours; the restored side unchanged.
    EXPECT_GT(colored(2, 0), 20000);
    EXPECT_LT(colored(2, 1), 50);
    // Wireframe on: dark lines over both meshes.
    EXPECT_LT(half(report, 3, 1)["mean_luminance"].get<double>(),
              half(report, 2, 1)["mean_luminance"].get<double>() - 2.0);
}

TEST_F(ViewerInBrowser, ViewRestoresTheInputWhenNoRestoredMeshIsGiven) {
    const CliRun view = resharp("view " + quoted(example_mesh()) + " -o " + path("page.html"));
    ASSERT_EQ(view.exit_code, 0) << view.stderr_text;
    const auto [code, report] = check("page.html");
    ASSERT_EQ(code, 0) << report.dump(2);
    EXPECT_EQ(report["viewer"]["hasSegments"], true);
    EXPECT_GT(report["viewer"]["restoredTriangles"].get<int>(),
              report["viewer"]["inputTriangles"].get<int>());
}

TEST_F(ViewerInBrowser, CheckerCatchesErrorsRequestsAndPagesThatNeverRender) {
    std::ofstream(dir_ / "error.html")
        << "<html><script>console.error('boom'); document.documentElement.dataset.status = "
           "'rendered';</script></html>";
    std::ofstream(dir_ / "throw.html")
        << "<html><script>document.documentElement.dataset.status = 'rendered'; "
           "null.property;</script></html>";
    std::ofstream(dir_ / "fetch.html")
        << "<html><img src='http://127.0.0.1:9/x.png'><script>"
           "document.documentElement.dataset.status = 'rendered';</script></html>";
    std::ofstream(dir_ / "silent.html") << "<html><body>never says</body></html>";

    const auto [error_code, error] = check("error.html");
    EXPECT_EQ(error_code, 1);
    EXPECT_NE(error["errors"].dump().find("boom"), std::string::npos) << error.dump(2);
    const auto [throw_code, thrown] = check("throw.html");
    EXPECT_EQ(throw_code, 1);
    EXPECT_NE(thrown["errors"].dump().find("TypeError"), std::string::npos) << thrown.dump(2);
    const auto [fetch_code, fetched] = check("fetch.html");
    EXPECT_EQ(fetch_code, 1);
    EXPECT_EQ(fetched["outside_requests"].size(), 1u) << fetched.dump(2);
    const auto [silent_code, silent] = check("silent.html", "--timeout 3");
    EXPECT_EQ(silent_code, 1);
    EXPECT_EQ(silent["status"], "timed out");
}

using ViewCommand = CliTest;

TEST_F(ViewCommand, RefusesSegmentsOfAnotherMeshAndWritesNothing) {
    std::ofstream(dir_ / "cube.off") << "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n"
                                        "1 1 1\n0 1 1\n3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n"
                                        "3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n"
                                        "3 2 7 6\n3 3 0 4\n3 3 4 7\n";
    ASSERT_EQ(restore(path("cube.off") + " -q -o " + path("cube.stl") + " --segments " +
                      path("cube-seg.ply"))
                  .exit_code,
              0);
    const CliRun run = resharp("view " + quoted(example_mesh()) + " --segments " +
                               path("cube-seg.ply") + " -o " + path("page.html"));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.stderr_text.find((dir_ / "cube-seg.ply").string() + ": "), std::string::npos)
        << run.stderr_text;
    EXPECT_NE(run.stderr_text.find("segments of another mesh"), std::string::npos)
        << run.stderr_text;
    EXPECT_FALSE(fs::exists(dir_ / "page.html"));

    const CliRun not_ply = resharp("view " + quoted(example_mesh()) + " --segments " +
                                   path("cube.stl") + " -o " + path("page.html"));
    EXPECT_EQ(not_ply.exit_code, 2);
    EXPECT_FALSE(fs::exists(dir_ / "page.html"));
}

TEST_F(ViewCommand, BatchWritesOnePagePerRestoredFile) {
    fs::create_directories(dir_ / "in");
    fs::copy_file(example_mesh(), dir_ / "in" / "part.stl");
    std::ofstream(dir_ / "in" / "broken.obj") << "v 0 0 0\nf 1 2 3\n";
    const CliRun run = restore(path("in") + " -o " + path("out") + " --html " + path("pages"));
    EXPECT_EQ(run.exit_code, 2) << run.stderr_text;
    ASSERT_TRUE(fs::exists(dir_ / "pages" / "part.html"));
    EXPECT_FALSE(fs::exists(dir_ / "pages" / "broken.html"));
    EXPECT_NE(bytes_of(dir_ / "pages" / "part.html").find("id=\"segment-roles\""),
              std::string::npos);
}

}  // namespace
}  // namespace resharp::cli
