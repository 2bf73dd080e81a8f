#pragma once
/// Every parameter of the method, one struct per stage. The paper's parameters default to the
/// paper's values; where resharp makes another choice than the paper (docs/method.md), the
/// default is ours and paper_variant() gives the paper's.
///   restore(mesh, {.features = {.max_normal_angle_deg = 6.0}});

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>

#include "resharp/near/vertex_moves.h"
#include "resharp/near/vertex_placement.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/harm_check.h"
#include "resharp/restoration/point_guard.h"
#include "resharp/restoration/sharp_points.h"
#include "resharp/segmentation/edge_segmentation.h"
#include "resharp/segmentation/feature_segmentation.h"

namespace resharp {

/// What restore() does with the artefacts of meshers before any stage runs.
struct MeshRepairOptions {
    /// Remove exact duplicate faces (same three vertices, same orientation), keeping the first
    /// copy, as simulators write them along their job seams. Pairs of opposite faces are kept
    /// either way (counted in the report).
    bool remove_duplicate_faces = true;
};

/// How restore() takes the vertices' placement (issue 14).
enum class VertexMode : std::uint8_t {
    Auto,      ///< measured from the mesh (estimate_vertex_placement()); exact when unclear
    Exact,     ///< on the surface: the paper's method, no vertex moves
    Near,      ///< near it (cell means of crossings): band vertices move within their cells
    Midpoint,  ///< at grid-edge midpoints: vertices move along their grid edges
};

struct VertexOptions {
    VertexMode mode = VertexMode::Auto;
    /// The grid the mesher worked on; a pitch of 0 has it inferred from the mesh, a pitch with
    /// no origin (grid_origin_given false) has the origin inferred for it. Without a grid,
    /// given or found, nothing moves (the exact path).
    Grid grid;
    bool grid_origin_given = false;
    VertexMoveOptions moves;
};

/// When a library caller wants restore() to give up (OpenVDB's interrupter is the model). It is
/// asked between stages and between rounds of the harm check, so it is honoured within one
/// stage's time (linear in the mesh); restore() then returns the input unchanged and says so.
struct StopWhen {
    /// Give up once the steady clock passes this.
    std::optional<std::chrono::steady_clock::time_point> deadline;
    /// Give up when this returns true (called from the thread that called restore()).
    std::function<bool()> cancelled;

    bool is_set() const { return deadline.has_value() || static_cast<bool>(cancelled); }
    bool should_stop() const {
        return (deadline && std::chrono::steady_clock::now() >= *deadline) ||
               (cancelled && cancelled());
    }
};

struct RestoreOptions {
    MeshRepairOptions repair;             ///< mesher artefacts: duplicate faces
    VertexOptions vertices;               ///< on, near or beside the surface (issue 14)
    EdgeSegmentationOptions edges;        ///< paper §3: eps_K, P, flatness
    FeatureSegmentationOptions features;  ///< paper §4: eps_theta, tiny patch size, merging
    ClassificationOptions bands;          ///< paper §4 (end): which borders are sharp edges
    FeatureNormalOptions normals;         ///< paper §5.1: eq. 5.1 or a linear fit
    SharpPointOptions points;             ///< paper §5.3: spike angle
    GuardOptions guard;                   ///< which points the split may insert
    HarmCheckOptions harm;                ///< the do-no-harm check after the split
    /// Rounds of guard, split and harm check at most. Each round after the first undoes at
    /// least one point or, near-surface, gives up at least one move, so the loop also ends when
    /// none is left; past this bound, restore() gives the input back unchanged (near-surface:
    /// restores it as an exact mesh, within as many rounds again).
    int max_harm_rounds = 8;
    /// Worker threads; 0 means all cores. The output does not depend on it.
    int threads = 0;
    /// Also return the per-vertex and per-face labels of both segmentations (for viewing what
    /// was detected, and for evaluation). Costs about 10 bytes per element.
    bool keep_segmentation = false;
    StopWhen stop;  ///< a deadline or a cancellation callback; none by default
};

/// `options` with the paper's choice wherever resharp offers another: k-means on signed
/// curvatures, region growing without a size limit, plain greedy merging, borders confirmed by
/// edge vertices alone, feature normals by eq. 5.1, points on tangent planes (eq. 5.2 / 5.3).
/// What the paper leaves open (docs/method.md, "our reading") and every other field stay as
/// given.
RestoreOptions paper_variant(RestoreOptions options);

/// Sets `vertices`' grid from the command line's --grid PITCH[,X,Y,Z] or Python's grid=(...):
/// the pitch, and where given a grid point (the origin).
/// \throws InvalidInput unless there are 1 or 4 finite numbers and the pitch is positive.
void set_grid(VertexOptions& vertices, std::span<const double> numbers);

}  // namespace resharp
