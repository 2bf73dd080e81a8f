#include "resharp/pipeline/report_json.h"

#include <string>

namespace resharp {
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
          {"tiny_patches_joined", r.tiny_patches_joined},
          {"merges", r.patch_merges}}},
        {"classification",
         {{"crossing_edges", r.crossing_edges},
          {"edge_triangles", r.edge_triangles},
          {"corner_triangles", r.corner_triangles}}},
        {"restoration",
         {{"edge_points_inserted", r.edge_points_inserted},
          {"face_points_inserted", r.face_points_inserted},
          {"corner_points_inserted", r.corner_points_inserted},
          {"refused_by_flip_test", r.refused_by_flip_test},
          {"refused_by_spike_test", r.refused_by_spike_test},
          {"first_order_points", r.first_order_points},
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
        {"vertices",
         {{"placement", std::string(r.vertex_placement)},
          {"measured", r.placement_measured},
          {"reason", r.placement_reason},
          {"grid_pitch", r.grid_pitch},
          {"moved", r.moved_vertices},
          {"largest_move", r.largest_move},
          {"moves_undone", r.moves_undone},
          {"rounds", r.move_rounds},
          {"bevels_dissolved", r.bevels_dissolved}}},
        {"mesh_repair",
         {{"duplicate_faces_removed", r.duplicate_faces_removed},
          {"opposite_face_pairs", r.opposite_face_pairs}}},
        {"output_unchanged", r.output_unchanged},
        {"unchanged_reason", std::string(r.unchanged_reason)},
        {"time_seconds", {{"stages", stages}, {"total", seconds(r.total_time)}}},
    };
}

}  // namespace resharp
