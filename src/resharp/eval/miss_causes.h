#pragma once
/// Why ideal points were missed: each ideal point the restoration did not put back gets one
/// cause, the first stage of the method that lost it (docs/results.md shows the counts).

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

#include "resharp/eval/ideal_points.h"
#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/restore.h"

namespace resharp::eval {

/// The causes, in the order the pipeline meets them, after the one no stage could help.
enum class MissCause {
    BeyondChord,        ///< the ideal point lies beyond the edge's chord: no split reaches it
    NoFeaturePatch,     ///< a vertex of the crossing edge joined no feature patch (§4)
    SamePatch,          ///< both vertices joined one feature patch (§4 merged or grew across)
    NoEdgeVertex,       ///< two patches, but neither vertex is an edge vertex (§3 missed it)
    CornerNotDetected,  ///< a corner triangle not classified as a corner triangle
    NotDetected,        ///< no labels per vertex: the faces are not edge or corner triangles
    NotInserted,        ///< detected, but no point was inserted there (flip, spike or quality
                        ///< test, or no feature normal)
    PlacedFar,          ///< a point was inserted there, farther than tau (feature normals off)
};
inline constexpr std::size_t kMissCauseCount = 8;

std::string_view miss_cause_name(MissCause cause);

struct MissCauses {
    /// Per cause (indexed by MissCause), edges and corners apart.
    std::array<std::size_t, kMissCauseCount> edges{};
    std::array<std::size_t, kMissCauseCount> corners{};
};

/// Assigns a cause to every ideal point off the boundary with `ideal_distance` above
/// `tolerance` (mm; see RestorationScore). `segmentation` as restore() keeps it: with labels
/// per vertex the causes are resolved stage by stage; with face roles only (read back from a
/// segments file) detection misses are NotDetected; with neither, only NotInserted and
/// PlacedFar are told apart. A point is "inserted there" when a new output vertex is joined to
/// both ends of the crossing edge (to all three corners of a corner triangle).
/// \throws InvalidInput if the output does not start with the input's vertices or the sizes of
/// `ideal` and `ideal_distance` differ.
MissCauses find_miss_causes(const Mesh& input, const Mesh& output,
                            std::span<const IdealPoint> ideal,
                            std::span<const double> ideal_distance, double tolerance,
                            const Segmentation& segmentation);

}  // namespace resharp::eval
