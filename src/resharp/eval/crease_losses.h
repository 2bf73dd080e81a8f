#pragma once
/// Why a restored CAD part's Edge F-score falls short (issue 14: "which edges fail and why, with
/// counts by cause"): every piece of a true sharp edge left farther than τ from the output's
/// sharp edges gets the first stage of restore() that lost it, read off what restore() kept
/// (RestoreResult::segmentation: band roles, point fates, planned moves); every piece of the
/// output's sharp edges farther than τ from the true ones gets where it came from. And the
/// output's faces turned against the exact surface, by what turned them.

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

#include "resharp/eval/cad_metrics.h"
#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/restore.h"

namespace resharp::eval {

/// Why a true sharp edge piece is missed, by the band faces within one grid pitch of it.
enum class CreaseLoss {
    NoBand,            ///< no edge or corner triangle near it: not detected (or dropped as smooth)
    NotPlaced,         ///< no candidate point (flip or spike test, or no feature normal)
    RefusedByGuard,    ///< candidates, all refused by the guard
    UndoneByHarm,      ///< accepted, then withdrawn by the harm check
    InsertedNoCrease,  ///< points inserted near it, but no output sharp edge within a pitch
    InsertedOff,       ///< points inserted, an output sharp edge within a pitch but beyond τ
};
inline constexpr std::size_t kCreaseLossCount = 6;
std::string_view crease_loss_name(CreaseLoss loss);

/// What became of the moves of the band vertices near a missed piece (near path only).
enum class MoveFate {
    None,    ///< no move planned for any of them (the exact path, or no trusted plane)
    Undone,  ///< moves planned, all given up (harm check or the exact-path fallback)
    Kept,    ///< one of them moved in the output
};
inline constexpr std::size_t kMoveFateCount = 3;
std::string_view move_fate_name(MoveFate fate);

/// Where an output sharp edge, or an output face, came from.
enum class Origin {
    Input,  ///< an input edge (face) whose vertices did not move
    Moves,  ///< an input edge (face) with a moved vertex
    Split,  ///< it has a new vertex: cut by the restoration
};
inline constexpr std::size_t kOriginCount = 3;
std::string_view origin_name(Origin origin);

struct CreaseLosses {
    /// True sharp edge length beyond τ of the output's, by loss and move fate (in `unit`).
    std::array<std::array<double, kMoveFateCount>, kCreaseLossCount> missed{};
    /// Output sharp edge length beyond τ of the true ones, by origin; `beside`: within a pitch of
    /// a true edge (a restored edge off by more than τ, or a band edge), the rest strays.
    std::array<double, kOriginCount> false_beside{}, false_stray{};
    double true_length = 0.0, mesh_length = 0.0;  ///< in `unit`
};

/// `input`: the mesh restore() was given; `output`: its result (input vertices first, where they
/// moved); `segmentation`: as restore() kept it (face roles and point fates needed); `exact`:
/// the true creases; `pitch`: the grid's (mm), the reach of "near"; `tolerance` τ and `unit` as
/// CreaseMetricsOptions; `sharp_angle_deg` and `spacing` as sample_mesh_creases().
/// \throws InvalidInput if the output does not extend the input or the segmentation lacks face
/// roles or point fates.
CreaseLosses find_crease_losses(const Mesh& input, const Mesh& output,
                                const Segmentation& segmentation, const CurveSamples& exact,
                                double pitch, double sharp_angle_deg, double spacing,
                                const CreaseMetricsOptions& options);

/// Per output face: where it came from (see Origin), judged by its corners' numbers and places.
Origin face_origin(const Mesh& input, const Mesh& output, const Triangle& face);

/// The flags of `flipped` (#F out) summed by face_origin(); a face identical to an input face
/// that `flipped_in_input` (#F in) marks counts as Input even with its vertices moved.
std::array<std::size_t, kOriginCount> flipped_by_origin(
    const Mesh& input, const Mesh& output, std::span<const std::uint8_t> flipped,
    std::span<const std::uint8_t> flipped_in_input);

}  // namespace resharp::eval
