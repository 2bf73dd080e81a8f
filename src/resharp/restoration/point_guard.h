#pragma once
/// The guard: decides which of the placed points the split may insert. It judges the pieces
/// each face would be cut into (restoration/pieces.h) against the surface's normals, and where
/// a piece would collapse or turn against the surface, repairs the face by dropping as few of
/// its points as it can. It changes nothing it is given: it returns the accepted slots.

#include <cstdint>
#include <span>

#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/input_surface.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp {

struct GuardOptions {
    /// Pieces joining vertices whose normals differ by more than this (degrees) stand across
    /// material too thin for the mesh and must clear each normal by twice the usual margin
    /// (by default the spike angle of §5.3).
    double thin_material_angle_deg = SharpPointOptions{}.spike_angle_deg;
};

struct GuardReport {
    std::size_t refused_by_quality = 0;  ///< points dropped: a piece would flip or collapse
    /// points dropped: a piece would turn against the face it replaces, or stand almost on
    /// edge across thin material
    std::size_t refused_by_guard = 0;
    /// faces repaired. Each repair drops at least one point from a slot or moves one edge's
    /// point onto its face's corner point (once per edge), so there are at most three times as
    /// many as slots holding a point at the start.
    std::size_t repairs = 0;
};

struct GuardedPoints {
    PointSlots accepted;  ///< the candidates' slots with the refused points cleared
    GuardReport report;
};

/// Takes the input surface, the feature normals with their fit corrections (#V), the placed
/// candidates and, per candidate point, whether a later check withdrew it (empty: none was).
/// Gives the slots whose every face splits into pieces that neither collapse nor turn against
/// their vertices' normals or the face they replace (docs/method.md, "The guard").
/// \throws InvalidInput if `withdrawn` is neither empty nor one entry per candidate point, or
///         the thin-material angle is not in (0, 180].
GuardedPoints guard_points(const InputSurface& input, const FeatureNormals& feature_normals,
                           const SharpPoints& candidates, std::span<const std::uint8_t> withdrawn,
                           const GuardOptions& options = {});

}  // namespace resharp
