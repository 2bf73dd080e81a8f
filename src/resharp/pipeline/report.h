#pragma once
/// What restore() found and did, stage by stage, with wall times.

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

#include "resharp/mesh/diagnostics.h"

namespace resharp {

/// The stages in the order restore() runs them. The paper's Table 1 groups them as edge-based
/// segmentation (Curvature, EdgeSegmentation), feature-based segmentation
/// (FeatureSegmentation) and edge and corner restoration (the rest). With a second thread, the
/// edge segmentation runs beside the feature regions' growth, and EdgeSegmentation holds only
/// the wait for it.
enum class Stage {
    MeshBuilding,         ///< adjacency, diagnostics, normals
    Curvature,            ///< local height intensity
    EdgeSegmentation,     ///< k-means and refinement (2+ threads: the wait for them)
    FeatureSegmentation,  ///< region growing, bands, tiny patches, merging
    Classification,       ///< edge and corner triangles
    FeatureNormals,       ///< eq. 5.1
    VertexMoves,          ///< near-surface meshes: vertices onto their fitted sides
    SharpPoints,          ///< eq. 5.2-5.5 and the spike test
    Guard,                ///< which points the split may insert (every round)
    Split,                ///< re-triangulation (every round)
    HarmCheck,            ///< the do-no-harm check (every round)
};
inline constexpr std::size_t kStageCount = 11;

std::string_view stage_name(Stage stage);

struct RestoreReport {
    MeshDiagnostics input;  ///< defects of the input mesh; processing goes on where it can

    std::size_t input_vertices = 0;
    std::size_t input_triangles = 0;
    std::size_t output_vertices = 0;
    std::size_t output_triangles = 0;

    std::size_t edge_vertices = 0;            ///< after refinement (§3)
    std::size_t clustered_edge_vertices = 0;  ///< straight out of k-means
    std::size_t isolated_edge_vertices_removed = 0;
    std::size_t bridge_vertices_added = 0;
    std::size_t flat_edge_vertices_removed = 0;
    int kmeans_iterations = 0;

    std::size_t feature_patches = 0;  ///< after absorbing and merging
    std::size_t grown_patches = 0;    ///< straight out of region growing
    std::size_t band_patches = 0;     ///< grown patches recognised as chamfer bands
    std::size_t tiny_patches_absorbed = 0;
    std::size_t tiny_patches_joined = 0;  ///< sets of tiny patches become one small surface
    std::size_t patch_merges = 0;

    std::size_t crossing_edges = 0;
    std::size_t edge_triangles = 0;
    std::size_t corner_triangles = 0;

    std::size_t edge_points_inserted = 0;
    /// of the edge points, those inside a face of their crossing edge (beyond its chord)
    std::size_t face_points_inserted = 0;
    std::size_t corner_points_inserted = 0;
    std::size_t refused_by_flip_test = 0;  ///< eq. 5.4
    /// §5.3: corner triangles, and on near-surface and midpoint meshes crossing edges
    /// (SharpPointOptions::edge_spike_angle_deg)
    std::size_t refused_by_spike_test = 0;
    std::size_t first_order_points = 0;      ///< second-order placement fell back to eq. 5.2/5.3
    std::size_t refused_missing_normal = 0;  ///< a vertex with no face on its own feature
    std::size_t refused_by_quality = 0;      ///< the guard: a split piece would flip or collapse
    std::size_t refused_by_guard = 0;        ///< the guard: a piece would turn against the face it
                                             ///< replaces or stand on edge across thin material
    std::size_t guard_repairs = 0;           ///< faces the guard repaired, over all rounds
    std::size_t split_triangles = 0;         ///< input faces replaced by pieces

    /// The do-no-harm check (docs/method.md, "Do no harm"): what it found in the first round,
    /// in pieces, and what undoing it took.
    std::size_t harm_turned = 0;    ///< pieces turned against the input surface
    std::size_t harm_folded = 0;    ///< pieces folded onto a neighbour
    std::size_t harm_crossing = 0;  ///< pieces meeting a nearby face
    std::size_t harm_rounds = 0;    ///< rounds of guard, split and check run (1 if none found)
    std::size_t undone_points = 0;  ///< accepted points withdrawn because their pieces did harm

    /// How the mesher placed the vertices (RestoreOptions::vertices, issue 14) and what
    /// near-surface restoration did about it.
    std::string_view vertex_placement = "exact";  ///< the path taken: exact, near or midpoint
    bool placement_measured = false;  ///< measured from the mesh, not named by the caller
    std::string placement_reason;     ///< what the measurement saw
    double grid_pitch = 0.0;          ///< of the grid moves were bounded by; 0 if none
    std::size_t moved_vertices = 0;   ///< input vertices moved in the output
    double largest_move = 0.0;        ///< mm
    /// Planned moves given up: those that turn a face over, before the restoration, those the
    /// harm check gave up within its rounds, and all of them where the rounds ran out.
    std::size_t moves_undone = 0;
    /// Restorations of a moved mesh checked against the input: 1 where vertices were to move
    /// (the moves the harm check gives up are given up within it), else 0.
    std::size_t move_rounds = 0;
    /// Near: patches, or pieces of patches, taken for a dual mesher's bevel across a concave edge
    /// and given back to the band before the moves (near/concave_bevels.h).
    std::size_t bevels_dissolved = 0;

    /// Mesher artefacts (MeshRepairOptions).
    std::size_t duplicate_faces_removed = 0;  ///< later copies of exact duplicate faces
    std::size_t opposite_face_pairs = 0;      ///< zero-thickness sheets, kept

    /// The output is the input (after duplicate removal) unchanged: nothing was restored.
    bool output_unchanged = false;
    /// Why, when the output is unchanged though there were points to insert: "cancelled"
    /// (RestoreOptions::stop), "harm rounds exhausted"; empty otherwise.
    std::string_view unchanged_reason;

    /// Wall time per stage, indexed by Stage.
    std::array<std::chrono::nanoseconds, kStageCount> stage_time{};
    std::chrono::nanoseconds total_time{};

    std::chrono::nanoseconds time(Stage stage) const {
        return stage_time[static_cast<std::size_t>(stage)];
    }
};

}  // namespace resharp
