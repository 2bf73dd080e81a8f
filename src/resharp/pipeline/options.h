#pragma once
/// Every parameter of the method, one struct per stage. The paper's parameters default to the
/// paper's values; where resharp makes another choice than the paper (docs/method.md), the
/// default is ours and paper_variant() gives the paper's.
///   restore(mesh, {.features = {.max_normal_angle_deg = 6.0}});

#include <chrono>
#include <functional>
#include <optional>

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
    EdgeSegmentationOptions edges;        ///< paper §3: eps_K, P, flatness
    FeatureSegmentationOptions features;  ///< paper §4: eps_theta, tiny patch size, merging
    ClassificationOptions bands;          ///< paper §4 (end): which borders are sharp edges
    FeatureNormalOptions normals;         ///< paper §5.1: eq. 5.1 or a linear fit
    SharpPointOptions points;             ///< paper §5.3: spike angle
    GuardOptions guard;                   ///< which points the split may insert
    HarmCheckOptions harm;                ///< the do-no-harm check after the split
    /// Rounds of guard, split and harm check at most. Each round after the first undoes at
    /// least one point, so the loop also ends when no point is left; past this bound, restore()
    /// gives the input back unchanged.
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
/// edge vertices alone, feature normals by eq. 5.1. What the paper leaves open (docs/method.md,
/// "our reading") and every other field stay as given.
RestoreOptions paper_variant(RestoreOptions options);

}  // namespace resharp
