// `resharp restore` as a user runs it: outputs and report on success, the same bytes whatever
// the thread count, and no output at all when a stage fails or memory runs out. Also
// `resharp evaluate` on the simulated example, for what its reference rows promise.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_run.h"

namespace resharp::cli {
namespace {

namespace fs = std::filesystem;

/// The shipped example, quoted.
std::string example() { return quoted(example_mesh()); }

using RestoreCli = CliTest;

TEST_F(RestoreCli, RestoresTheExampleWithReportSegmentsAndSummary) {
    const CliRun run = restore(example() + " -o " + path("out.stl") + " --report " +
                               path("report.json") + " --segments " + path("segments.ply"));
    ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
    EXPECT_NE(run.stderr_text.find("triangles in"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir_ / "out.stl"));
    EXPECT_TRUE(fs::exists(dir_ / "segments.ply"));
    const auto report = nlohmann::json::parse(bytes_of(dir_ / "report.json"));
    EXPECT_EQ(report["input"]["triangles"], 39748);
    EXPECT_GT(report["restoration"]["edge_points_inserted"].get<int>(), 2000);
    EXPECT_EQ(report["output"]["vertices"].get<int>(),
              report["input"]["vertices"].get<int>() +
                  report["restoration"]["edge_points_inserted"].get<int>() +
                  report["restoration"]["corner_points_inserted"].get<int>());
    EXPECT_TRUE(report["time_seconds"]["stages"].contains("split"));
}

// The split on the oracle's bands with exact normals (the ceiling of an edge split): the bracket
// is planes and cylinders, so every ideal point on the exact junction is restored and nothing
// folds. Every crossing edge gets its first-order (eq. 5.2) ideal point but two, whose points lie
// past a corner on their edges' extension: there the guard splits the edge at the corner point
// instead (docs/method.md, "Edge points beyond the corner"). Nothing is counted apart but the
// junctions under the slot's floor.
TEST_F(RestoreCli, EvaluatesTheSplitCeilingOfTheSimulatedBracket) {
    const std::string job =
        quoted(fs::path(RESHARP_SOURCE_DIR) / "examples" / "bracket" / "job.json");
    const CliRun simulated = resharp("simulate " + job + " -o " + path("in.ply") + " --oracle " +
                                     path("oracle.ply") + " -q");
    ASSERT_EQ(simulated.exit_code, 0) << simulated.stderr_text;
    const std::string evaluate =
        "evaluate --input " + path("in.ply") + " --oracle " + path("oracle.ply") + " --job " + job;
    const CliRun run = resharp(evaluate + " --restore --oracle-bands --json " + path("r.json"));
    ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
    const auto r = nlohmann::json::parse(bytes_of(dir_ / "r.json"));
    EXPECT_EQ(r["detection_source"], "the oracle (--oracle-bands)");
    EXPECT_EQ(r["detection_precision"], 1.0);
    EXPECT_EQ(r["detection_recall"], 1.0);
    EXPECT_GT(r["ideal_points"]["edges"].get<int>(), 1000);
    const auto& first_order = r["first_order"]["ideal_points"];
    EXPECT_EQ(first_order["restored_edges"].get<int>() + 2, first_order["edges"].get<int>());
    EXPECT_EQ(r["first_order"]["restoration_rate_corners"], 1.0);
    EXPECT_EQ(r["restoration_rate_first_order"], r["first_order"]["restoration_rate"]);
    EXPECT_EQ(r["restoration_rate"], 1.0);
    const auto& apart = r["ideal_points"]["counted_apart"];
    EXPECT_EQ(apart["sampled_surface"]["edges"], 0);
    EXPECT_EQ(apart["unsolved"]["edges"], 0);
    EXPECT_LE(apart["not_bounding"]["edges"].get<int>(), 4);
    EXPECT_NE(run.stderr_text.find("on the exact junction"), std::string::npos) << run.stderr_text;
    // On the exact junction only the points of junctions counted apart have no ideal point.
    EXPECT_EQ(r["first_order"]["false_insertions"], 0);
    EXPECT_LE(r["false_insertions"], r["ideal_points"]["counted_apart"]["not_bounding"]["edges"]);
    EXPECT_EQ(r["flipped_triangles"], 0);
    EXPECT_EQ(r["self_intersections"], 0);

    const CliRun without_restore =
        resharp(evaluate + " --output " + path("in.ply") + " --oracle-bands");
    EXPECT_EQ(without_restore.exit_code, 1);
    EXPECT_NE(without_restore.stderr_text.find("--oracle-bands requires --restore"),
              std::string::npos)
        << without_restore.stderr_text;
}

TEST_F(RestoreCli, SameBytesWithOneThreadAndTwo) {
    ASSERT_EQ(restore(example() + " -q --threads 1 -o " + path("one.stl")).exit_code, 0);
    ASSERT_EQ(restore(example() + " -q --threads 2 -o " + path("two.stl")).exit_code, 0);
    const std::string one = bytes_of(dir_ / "one.stl");
    EXPECT_GT(one.size(), 84u);
    EXPECT_EQ(one, bytes_of(dir_ / "two.stl"));
}

TEST_F(RestoreCli, AnErrorInsideAStageLeavesNoOutput) {
    // The option is read by feature segmentation, which refuses it after the mesh was read and
    // the earlier stages ran.
    const CliRun run = restore(example() + " --region-angle 0 -o " + path("out.stl") +
                               " --report " + path("report.json"));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.stderr_text.find("resharp: error: region growing angle"), std::string::npos)
        << run.stderr_text;
    EXPECT_TRUE(outputs().empty());
}

TEST_F(RestoreCli, PaperVariantRunsAndRefusesTheChoicesItSets) {
    EXPECT_EQ(restore(example() + " -q --paper -o " + path("paper.stl")).exit_code, 0);
    EXPECT_NE(bytes_of(dir_ / "paper.stl"), "");
    const CliRun run = restore(example() + " --paper --normals fit -o " + path("both.stl"));
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.stderr_text.find("excludes"), std::string::npos) << run.stderr_text;
    EXPECT_FALSE(fs::exists(dir_ / "both.stl"));
}

// A surface-nets mesh as a user meets one: measured as near, band vertices moved within their
// cells, and said so; a bad --grid refused on the command line, nothing written.
TEST_F(RestoreCli, MeasuresASurfaceNetsMeshAndMovesItsBandVertices) {
    const std::string job =
        quoted(fs::path(RESHARP_SOURCE_DIR) / "examples" / "bracket" / "job.json");
    const CliRun simulated =
        resharp("simulate " + job + " --mesher surface-nets -o " + path("in.ply") + " -q");
    ASSERT_EQ(simulated.exit_code, 0) << simulated.stderr_text;
    const CliRun run =
        restore(path("in.ply") + " -o " + path("out.ply") + " --report " + path("report.json"));
    ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
    EXPECT_NE(run.stderr_text.find("vertices near the surface (measured"), std::string::npos)
        << run.stderr_text;
    const auto v = nlohmann::json::parse(bytes_of(dir_ / "report.json"))["vertices"];
    EXPECT_EQ(v["placement"], "near");
    EXPECT_EQ(v["measured"], true);
    EXPECT_DOUBLE_EQ(v["grid_pitch"].get<double>(), 0.5);  // the job's pitch
    EXPECT_GT(v["moved"].get<int>(), 100);
    EXPECT_LE(v["largest_move"].get<double>(), std::sqrt(3.0) * 0.5);

    const CliRun exact = restore(path("in.ply") + " -q --vertices exact -o " + path("exact.ply") +
                                 " --report " + path("exact.json"));
    ASSERT_EQ(exact.exit_code, 0) << exact.stderr_text;
    EXPECT_EQ(nlohmann::json::parse(bytes_of(dir_ / "exact.json"))["vertices"]["moved"], 0);

    const CliRun bad = restore(path("in.ply") + " --grid 0.5,1 -o " + path("bad.ply"));
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.stderr_text.find("--grid"), std::string::npos) << bad.stderr_text;
    EXPECT_FALSE(fs::exists(dir_ / "bad.ply"));
}

TEST_F(RestoreCli, SegmentsMustBePly) {
    const CliRun run =
        restore(example() + " -o " + path("out.stl") + " --segments " + path("segments.stl"));
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_TRUE(outputs().empty());
}

#if !defined(__SANITIZE_ADDRESS__)
// AddressSanitizer reserves terabytes of address space at start, which no `ulimit -v` allows;
// the Release run of the suite covers this.
TEST_F(RestoreCli, OutOfMemoryExitsFourAndLeavesNoOutput) {
    // 16 MB of address space: the program starts, but reading and restoring the example (about
    // 20 MB at peak) runs out. Where exactly it runs out depends on the machine; the contract
    // does not.
    const CliRun run =
        restore(example() + " -o " + path("out.stl") + " --report " + path("report.json"),
                "ulimit -v 16000; ");
    EXPECT_EQ(run.exit_code, 4) << run.stderr_text;
    EXPECT_EQ(run.stderr_text.rfind("resharp: error: ", 0), 0u) << run.stderr_text;
    EXPECT_TRUE(outputs().empty());
}
#endif

}  // namespace
}  // namespace resharp::cli

namespace resharp::cli {
namespace {

/// One part of the CAD corpus (examples/cad) sampled at `cells`, restored and evaluated; the
/// "cad" block of evaluate's JSON. `rotated`: the part turned off the grid axes first, as
/// bench/cad_corpus.py turns it.
class CadCorpusCli : public RestoreCli {
protected:
    nlohmann::json measure(const std::string& part, bool rotated, int cells) const {
        fs::path solid = fs::path(RESHARP_SOURCE_DIR) / "examples" / "cad" / (part + ".json");
        if (rotated) {
            std::ifstream in(solid);
            const auto file = nlohmann::json::parse(in, nullptr, true, /*ignore_comments=*/true);
            const nlohmann::json turned = {{"solid",
                                            {{"union", {file["solid"]}},
                                             {"rotate", {{"axis", {2, -1, 3}}, {"degrees", 27}}}}}};
            solid = dir_ / (part + "_rotated.json");
            std::ofstream(solid) << turned.dump();
        }
        const std::string grid = " --cells " + std::to_string(cells) + " -q";
        const CliRun simulated = resharp("simulate --solid " + quoted(solid) + " -o " +
                                         path("in.ply") + " --oracle " + path("oracle.ply") + grid);
        EXPECT_EQ(simulated.exit_code, 0) << simulated.stderr_text;
        const CliRun restored = restore(path("in.ply") + " -o " + path("out.ply") + " -q");
        EXPECT_EQ(restored.exit_code, 0) << restored.stderr_text;
        const CliRun evaluated = resharp(
            "evaluate --input " + path("in.ply") + " --oracle " + path("oracle.ply") + " --solid " +
            quoted(solid) + " --output " + path("out.ply") + " --json " + path("r.json") + grid);
        EXPECT_EQ(evaluated.exit_code, 0) << evaluated.stderr_text;
        return nlohmann::json::parse(bytes_of(dir_ / "r.json"))["cad"];
    }

    /// Every measure is a number, and the true sharp edges were found.
    static void expect_measured(const nlohmann::json& cad) {
        for (const char* side : {"input", "output"}) {
            for (const char* key : {"chamfer", "hausdorff", "normal_consistency",
                                    "edge_chamfer_distance", "edge_f1", "crease_length_ratio"}) {
                EXPECT_TRUE(cad[side][key].is_number()) << side << " " << key << ": " << cad;
            }
            EXPECT_GT(cad[side]["true_crease_length"].get<double>(), 1.0) << cad;
        }
    }
};

// The subset of the corpus CI runs: plane-only parts, aligned and rotated, at 50 cells, where
// restoring must not make any measure worse than the input's.
TEST_F(CadCorpusCli, PlaneOnlyPartsComeBackNoWorse) {
    for (const auto& [part, rotated] :
         {std::pair{"stepped_block", false}, std::pair{"hex_prism", true}}) {
        const nlohmann::json cad = measure(part, rotated, 50);
        expect_measured(cad);
        const nlohmann::json &in = cad["input"], &out = cad["output"];
        EXPECT_LE(out["chamfer"], in["chamfer"]) << part;
        EXPECT_LE(out["hausdorff"], in["hausdorff"]) << part;
        EXPECT_GE(out["normal_consistency"], in["normal_consistency"]) << part;
        EXPECT_LE(out["edge_chamfer_distance"], in["edge_chamfer_distance"]) << part;
        EXPECT_GE(out["edge_f1"], in["edge_f1"]) << part;
    }
}

// A curved part (fillets, plane-cylinder and plane-sphere edges) is measured; whether restoring
// it helps is what docs/results.md reports.
TEST_F(CadCorpusCli, CurvedPartIsMeasured) { expect_measured(measure("fillet_boss", false, 50)); }

TEST_F(CadCorpusCli, BadSolidFileExitsTwoNamingThePlaceAndWritesNothing) {
    std::ofstream(dir_ / "bad.json")
        << R"({"solid": {"difference": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}},
                                        {"sphere": {"center": [0, 0, 0], "radius": "big"}}]}})";
    const CliRun run = resharp("simulate --solid " + path("bad.json") + " -o " + path("out.stl"));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.stderr_text, "resharp: error: " + (dir_ / "bad.json").string() +
                                   ": solid.difference[1].sphere.radius: must be a number\n");
    EXPECT_FALSE(fs::exists(dir_ / "out.stl"));
}

}  // namespace
}  // namespace resharp::cli
