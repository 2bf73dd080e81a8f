#pragma once
/// Every parameter of the method, one struct per stage. The paper's parameters default to the
/// paper's values; where resharp makes another choice than the paper (docs/method.md), the
/// default is ours and paper_variant() gives the paper's.
///   restore(mesh, {.features = {.max_normal_angle_deg = 6.0}});

#include <span>

#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/sharp_points.h"
#include "resharp/restoration/split.h"
#include "resharp/segmentation/edge_segmentation.h"
#include "resharp/segmentation/feature_segmentation.h"

namespace resharp {

struct RestoreOptions {
    EdgeSegmentationOptions edges;        ///< paper §3: eps_K, P, flatness
    FeatureSegmentationOptions features;  ///< paper §4: eps_theta, tiny patch size, merging
    ClassificationOptions bands;          ///< paper §4 (end): which borders are sharp edges
    FeatureNormalOptions normals;         ///< paper §5.1: eq. 5.1 or a linear fit
    SharpPointOptions points;             ///< paper §5.3: spike angle
    /// The split guard's clearance check (SplitOptions::check_clearance): off by default.
    bool check_clearance = false;
    /// Worker threads; 0 means all cores. The output does not depend on it.
    int threads = 0;
    /// Also return the per-vertex and per-face labels of both segmentations (for viewing what
    /// was detected, and for evaluation). Costs about 10 bytes per element.
    bool keep_segmentation = false;
    /// If not empty (#V unit normals), used in place of the feature normals of eq. 5.1 at every
    /// band vertex. For evaluation: with the simulator's exact normals it shows the ceiling of
    /// the placement step. The caller keeps the data alive during restore().
    std::span<const Vec3> normal_override;
};

/// `options` with the paper's choice wherever resharp offers another: k-means on signed
/// curvatures, region growing without a size limit, plain greedy merging, borders confirmed by
/// edge vertices alone, feature normals by eq. 5.1. What the paper leaves open (docs/method.md,
/// "our reading") and every other field stay as given.
RestoreOptions paper_variant(RestoreOptions options);

}  // namespace resharp
