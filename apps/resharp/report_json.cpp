#include "report_json.h"

#include <iomanip>
#include <sstream>

namespace resharp::cli {
namespace {

double seconds(std::chrono::nanoseconds t) { return std::chrono::duration<double>(t).count(); }

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

/// The vertex placement, where it is not the exact path: "; vertices near the surface (measured:
/// REASON), 1200 moved, at most 0.21 mm, 3 moves undone".
std::string vertices_summary(const RestoreReport& r) {
    if (r.vertex_placement == "exact") return {};
    std::ostringstream text;
    text << std::fixed << std::setprecision(3) << "; vertices "
         << (r.vertex_placement == "near" ? "near the surface" : "at grid-edge midpoints") << " ("
         << (r.placement_measured ? "measured: " + r.placement_reason : "as given") << "), "
         << r.moved_vertices << " moved, at most " << r.largest_move << " mm, " << r.moves_undone
         << " moves undone";
    return text.str();
}

}  // namespace

std::string summarize(const RestoreReport& r, const std::string& input, const std::string& output) {
    // One figure for both segmentations: on two threads they run at once (pipeline/report.h).
    const double segmentation_time =
        seconds(r.time(Stage::Curvature) + r.time(Stage::EdgeSegmentation) +
                r.time(Stage::FeatureSegmentation));
    const double restore_time =
        seconds(r.time(Stage::Classification) + r.time(Stage::FeatureNormals) +
                r.time(Stage::SharpPoints) + r.time(Stage::VertexMoves) + r.time(Stage::Guard) +
                r.time(Stage::Split) + r.time(Stage::HarmCheck));
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
         << vertices_summary(r)
         << (r.duplicate_faces_removed > 0
                 ? "; removed " + std::to_string(r.duplicate_faces_removed) + " duplicate faces"
                 : std::string())
         << (r.unchanged_reason.empty() ? std::string()
                                        : "; output unchanged: " + std::string(r.unchanged_reason))
         << ". Input defects: " << describe_defects(r.input) << ". Time " << seconds(r.total_time)
         << " s (mesh " << seconds(r.time(Stage::MeshBuilding)) << ", segmentation "
         << segmentation_time << ", restoration " << restore_time << ").\n";
    return text.str();
}

}  // namespace resharp::cli
