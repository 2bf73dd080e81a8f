#include "report_json.h"

#include <iomanip>
#include <sstream>

namespace resharp::cli {
namespace {

double seconds(std::chrono::nanoseconds t) { return std::chrono::duration<double>(t).count(); }

nlohmann::json defects_to_json(const MeshDiagnostics& d) {
    return {{"boundary_edges", d.boundary_edges},
            {"nonmanifold_edges", d.nonmanifold_edges},
            {"inconsistent_edges", d.inconsistent_edges},
            {"nonmanifold_vertices", d.nonmanifold_vertices},
            {"degenerate_faces", d.degenerate_faces},
            {"duplicate_faces", d.duplicate_faces},
            {"isolated_vertices", d.isolated_vertices},
            {"components", d.components}};
}

std::string describe_defects(const MeshDiagnostics& d) {
    std::string text;
    auto add = [&](std::size_t count, const char* what) {
        if (count == 0) return;
        text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + what;
    };
    add(d.boundary_edges, "boundary edges");
    add(d.nonmanifold_edges, "non-manifold edges");
    add(d.inconsistent_edges, "edges with flipped orientation");
    add(d.nonmanifold_vertices, "non-manifold vertices");
    add(d.degenerate_faces, "degenerate faces");
    add(d.duplicate_faces, "duplicate faces");
    add(d.isolated_vertices, "isolated vertices");
    if (d.components > 1) add(d.components, "components");
    return text.empty() ? "none" : text + " (left unchanged)";
}

}  // namespace

nlohmann::json report_to_json(const RestoreReport& r) {
    nlohmann::json stages = nlohmann::json::object();
    for (std::size_t s = 0; s < kStageCount; ++s) {
        stages[std::string(stage_name(static_cast<Stage>(s)))] = seconds(r.stage_time[s]);
    }
    return {
        {"input",
         {{"vertices", r.input_vertices},
          {"triangles", r.input_triangles},
          {"defects", defects_to_json(r.input)}}},
        {"output", {{"vertices", r.output_vertices}, {"triangles", r.output_triangles}}},
        {"edge_segmentation",
         {{"edge_vertices", r.edge_vertices},
          {"clustered_edge_vertices", r.clustered_edge_vertices},
          {"isolated_removed", r.isolated_edge_vertices_removed},
          {"bridge_vertices_added", r.bridge_vertices_added},
          {"flat_removed", r.flat_edge_vertices_removed},
          {"kmeans_iterations", r.kmeans_iterations}}},
        {"feature_segmentation",
         {{"feature_patches", r.feature_patches},
          {"grown_patches", r.grown_patches},
          {"band_patches", r.band_patches},
          {"tiny_patches_absorbed", r.tiny_patches_absorbed},
          {"merges", r.patch_merges}}},
        {"classification",
         {{"crossing_edges", r.crossing_edges},
          {"edge_triangles", r.edge_triangles},
          {"corner_triangles", r.corner_triangles}}},
        {"restoration",
         {{"edge_points_inserted", r.edge_points_inserted},
          {"corner_points_inserted", r.corner_points_inserted},
          {"refused_by_flip_test", r.refused_by_flip_test},
          {"refused_by_spike_test", r.refused_by_spike_test},
          {"refused_missing_normal", r.refused_missing_normal},
          {"refused_by_quality", r.refused_by_quality},
          {"refused_by_guard", r.refused_by_guard},
          {"guard_repairs", r.guard_repairs},
          {"split_triangles", r.split_triangles}}},
        {"harm_check",
         {{"turned", r.harm_turned},
          {"folded", r.harm_folded},
          {"crossing", r.harm_crossing},
          {"rounds", r.harm_rounds},
          {"undone_points", r.undone_points}}},
        {"mesh_repair",
         {{"duplicate_faces_removed", r.duplicate_faces_removed},
          {"opposite_face_pairs", r.opposite_face_pairs}}},
        {"output_unchanged", r.output_unchanged},
        {"unchanged_reason", std::string(r.unchanged_reason)},
        {"time_seconds", {{"stages", stages}, {"total", seconds(r.total_time)}}},
    };
}

std::string summarize(const RestoreReport& r, const std::string& input, const std::string& output) {
    const double edge_time = seconds(r.time(Stage::Curvature) + r.time(Stage::EdgeSegmentation));
    const double feature_time = seconds(r.time(Stage::FeatureSegmentation));
    const double restore_time = seconds(
        r.time(Stage::Classification) + r.time(Stage::FeatureNormals) + r.time(Stage::SharpPoints) +
        r.time(Stage::Guard) + r.time(Stage::Split) + r.time(Stage::HarmCheck));
    std::ostringstream text;
    text << std::fixed << std::setprecision(3);
    text << "resharp: " << input << " -> " << output << ": " << r.input_triangles
         << " triangles in, " << r.output_triangles << " out. Found " << r.edge_vertices
         << " edge vertices, " << r.feature_patches << " feature patches, " << r.edge_triangles
         << " edge and " << r.corner_triangles << " corner triangles; inserted "
         << r.edge_points_inserted << " edge and " << r.corner_points_inserted
         << " corner points (refused: " << r.refused_by_flip_test << " by the flip test, "
         << r.refused_by_spike_test << " by the spike test, " << r.refused_by_quality
         << " for quality, " << r.refused_by_guard << " by the guard, " << r.refused_missing_normal
         << " without a feature normal; " << r.undone_points << " undone by the harm check in "
         << r.harm_rounds << (r.harm_rounds == 1 ? " round" : " rounds") << ")"
         << (r.duplicate_faces_removed > 0
                 ? "; removed " + std::to_string(r.duplicate_faces_removed) + " duplicate faces"
                 : std::string())
         << (r.unchanged_reason.empty() ? std::string()
                                        : "; output unchanged: " + std::string(r.unchanged_reason))
         << ". Input defects: " << describe_defects(r.input) << ". Time " << seconds(r.total_time)
         << " s (mesh " << seconds(r.time(Stage::MeshBuilding)) << ", edge segmentation "
         << edge_time << ", feature segmentation " << feature_time << ", restoration "
         << restore_time << ").\n";
    return text.str();
}

}  // namespace resharp::cli
