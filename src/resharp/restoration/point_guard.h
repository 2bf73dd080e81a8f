#pragma once
/// The guard: decides which of the placed points the split may insert. It judges the pieces
/// each face would be cut into (restoration/pieces.h) against the surface's normals, and where
/// a piece would collapse or turn against the surface, repairs the face by dropping as few of
/// its points as it can. It changes nothing it is given: it returns the accepted slots.

#include <cstdint>
#include <span>
#include <vector>

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
    /// faces repaired. Each repair drops at least one point from a slot, or puts onto an edge
    /// (once per edge) its face's corner point, another edge's point of its face (a merge), or
    /// the corner point of a face across its face's other edge (a spread), so there are at most
    /// as many as slots holding a point at the start plus edges.
    std::size_t repairs = 0;
};

/// One repair as the guard made it.
struct GuardRepair {
    Index face = kNoIndex;      ///< the face repaired
    bool by_quality = false;    ///< its fault: quality (true) or the guard's own (false)
    std::uint32_t dropped = 0;  ///< points it dropped
};

struct GuardedPoints {
    PointSlots accepted;  ///< the candidates' slots with the refused points cleared
    GuardReport report;   ///< the sums of `repairs`
    /// Every repair made, in the order made (guard_points_again(): those it kept first, then
    /// those it made): what a later round keeps of the faces it need not guard again.
    std::vector<GuardRepair> repairs;
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

/// A later round's guard: takes what guard_points() takes, the result `previous` it gave for
/// the withdrawal flags `withdrawn_before` (empty: none), the flags `withdrawn` now (a
/// superset), and `holders`, faces whose slots in `previous` held every point withdrawn since
/// (such as the faces the harm check found harmful); gives exactly what guard_points() gives
/// for `withdrawn` (slots, report, and the same repairs in another order), guarding again only
/// the faces whose work can differ. The guard's work on a face reads and writes the slots of
/// the face and of the faces across its edges and nothing else, so the faces beyond a border
/// of faces the last run left alone (never repaired, slots as they started) keep their slots
/// and repairs as long as this run leaves that border alone too; where it does not, the region
/// grows past it and is guarded again. `reshaped`: faces whose work reads a part of `input`
/// that changed since `previous` (near-surface restoration puts moved vertices back: the faces
/// within three rings of them), guarded again as the holders' faces are.
/// \throws InvalidInput as guard_points() does, if `withdrawn_before` is neither empty nor one
///         flag per candidate point, or if a holder or a reshaped face is not a face.
GuardedPoints guard_points_again(const InputSurface& input, const FeatureNormals& feature_normals,
                                 const SharpPoints& candidates, const GuardedPoints& previous,
                                 std::span<const std::uint8_t> withdrawn_before,
                                 std::span<const std::uint8_t> withdrawn,
                                 std::span<const Index> holders, std::span<const Index> reshaped,
                                 const GuardOptions& options = {});

}  // namespace resharp
