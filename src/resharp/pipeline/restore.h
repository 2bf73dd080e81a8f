#pragma once
/// The one entry point, restore(): the whole method of the paper on an indexed triangle mesh,
/// guarded so that it never makes a mesh worse. Its two halves are public too, for callers
/// that put their own data between them (evaluation with exact normals, benchmarks).

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/options.h"
#include "resharp/pipeline/report.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/input_surface.h"
#include "resharp/restoration/split.h"
#include "resharp/segmentation/edge_segmentation.h"
#include "resharp/segmentation/feature_segmentation.h"

namespace resharp {

/// How far the sharp points of an edge or corner triangle got (restore_bands()), the first
/// stage that stopped them; what the evaluation's diagnosis reads (eval/crease_losses.h).
enum class PointFate : std::uint8_t {
    None,            ///< not an edge or corner triangle
    NotPlaced,       ///< no candidate: the flip or spike test refused it, or a normal was missing
    RefusedByGuard,  ///< every candidate refused by the guard
    UndoneByHarm,    ///< accepted by the guard, then withdrawn by the harm check
    Inserted,        ///< a point of it is in the output
};

/// What both segmentations found, on the input mesh's elements, and what became of the points
/// and moves planned on them.
struct Segmentation {
    std::vector<std::uint8_t> is_edge_vertex;  ///< per input vertex (#V): edge-based result, §3
    /// Per input vertex (#V): feature patch, or kNoIndex. On a near-surface mesh, the patches
    /// the moved mesh was restored with: concave bevels dissolved, and a vertex moved onto
    /// another patch's face in that patch (near/vertex_moves.h).
    std::vector<Index> vertex_patch;
    std::vector<Index> face_patch;      ///< per input face (#F): feature patch, kNoIndex in bands
    std::vector<BandRole> face_role;    ///< per input face (#F): edge or corner triangle
    std::vector<PointFate> point_fate;  ///< per input face (#F)
    /// Per input vertex (#V): 1 where the near path planned a move (kept or undone); empty on
    /// the exact path.
    std::vector<std::uint8_t> move_planned;
};

struct RestoreResult {
    /// The restored mesh: the input vertices first and in order, then the new points on sharp
    /// edges and corners, so output vertex i < #V in is input vertex i and the others come from
    /// no input vertex; faces in input order (less removed duplicates), each unchanged or
    /// replaced in place by its pieces. Input vertices keep their positions bit for bit, except
    /// on a near-surface mesh (report.vertices: placement near or midpoint), where some move
    /// within their grid cell or along their grid edge (report.vertices counts them and gives
    /// the largest move).
    Mesh mesh;
    /// Per output face (#F out): the input face it is or was cut from, so that callers can
    /// carry face attributes (tool ids, colours) over.
    std::vector<Index> source_face;
    RestoreReport report;
    /// Filled only when RestoreOptions::keep_segmentation is set; removed duplicate faces
    /// have no patch and no role.
    Segmentation segmentation;
};

/// Paper §3-§5: finds the chamfer bands a grid-based simulation leaves along sharp edges and
/// corners and restores the sharp edges by inserting points on them. Input vertices of an
/// exact-crossing mesh never move; those of a near-surface mesh move only within what their
/// mesher could have got wrong (VertexOptions, docs/method.md).
/// Exact duplicate faces are removed first (MeshRepairOptions). Every output face that replaces
/// an input face is checked against the input surface; what fails is undone (docs/method.md,
/// "Do no harm"). Defects (boundaries, non-manifold edges, degenerate faces) are counted in the
/// report and left unchanged; restoration goes on elsewhere. The same input and options give
/// the same output whatever the thread count. When RestoreOptions::stop fires, the input comes
/// back unchanged with report.output_unchanged set.
/// \throws InvalidInput if the mesh has no triangles, an index out of range or a non-finite
///         coordinate, or an option is out of range.
RestoreResult restore(const Mesh& input, const RestoreOptions& options = {});

/// restore() of a mesh its caller gives up: the same result, but where exact duplicate faces
/// are removed they are dropped from `input` itself instead of from a copy, which held a second
/// mesh through the whole restoration (relief_hang.stl: 2.6 MiB, 24 bytes per input triangle).
/// Cancelled, it puts them back: `input` is then as it came. Otherwise what it holds after is
/// unspecified.
RestoreResult restore(Mesh&& input, const RestoreOptions& options = {});

/// The first half of restore(), from mesh building to the feature normals (§3-§5.1).
struct Detection {
    /// Shared by the detections of meshes with the same faces (the input and its moved copies
    /// in near-surface restoration), which would otherwise each hold a copy (peak memory).
    std::shared_ptr<const Connectivity> connectivity;
    SurfaceNormals normals;
    EdgeSegmentation edges;
    FeatureSegmentation features;
    BandClassification bands;
    FeatureNormals feature_normals;
    std::array<std::chrono::nanoseconds, kStageCount> stage_time{};  ///< of the stages run

    InputSurface surface(const Mesh& mesh) const { return {mesh, *connectivity, normals}; }
};

/// Takes the mesh and its connectivity; runs the stages up to the feature normals.
/// \throws Cancelled when options.stop fires between two stages; InvalidInput for options
///         out of range.
Detection detect_bands(const Mesh& mesh, std::shared_ptr<const Connectivity> connectivity,
                       const RestoreOptions& options);
/// detect_bands() of a connectivity no other detection shares.
Detection detect_bands(const Mesh& mesh, Connectivity connectivity, const RestoreOptions& options);

/// detect_bands() on `mesh`, the input with the vertices flagged in `moved` (#V) moved, its
/// faces the same (near-surface restoration): the connectivity shared with `before` and the
/// segmentations carried over from it (a patch is a set of faces; moving vertices within their
/// cells keeps them), the normals made anew where the moves change them (the rest are the
/// input's `unmoved` normals, which the detection takes), classification and feature normals
/// made anew on `mesh`.
/// \throws as detect_bands().
Detection detect_bands_after_moves(const Mesh& mesh, const Detection& before,
                                   SurfaceNormals unmoved, std::span<const std::uint8_t> moved,
                                   const RestoreOptions& options);

/// The second half of restore(): points placed on the bands (eq. 5.2-5.5), then rounds of
/// guard, split and harm check; each round withdraws the points of the faces whose pieces did
/// harm (or, near-surface, gives up moves), until a round finds none (at most
/// options.max_harm_rounds rounds; each round but the first has at least one point or one move
/// fewer).
struct BandRestoration {
    SplitMesh output;     ///< the last round's split; the input itself when given up
    SharpPoints points;   ///< the placed candidates
    PointSlots accepted;  ///< the last round's guarded slots, the points `output` holds
    std::vector<std::uint8_t> withdrawn;  ///< per candidate (#P): withdrawn by the harm check
    GuardReport guard;                    ///< summed over the rounds
    HarmReport first_harm;                ///< what the first round's check found
    std::size_t rounds = 0;
    std::size_t undone_points = 0;
    std::size_t moves_given_up = 0;  ///< vertices put back by `give_up_moves`
    bool rounds_exhausted = false;   ///< harm remained after the last round: nothing inserted
    std::array<std::chrono::nanoseconds, kStageCount> stage_time{};  ///< of the stages run
};

/// What restore_bands() holds its split against when that is not the surface it splits: the
/// input places of that surface's vertices, and the flags of the vertices moved from them
/// (#V each; near-surface restoration). The split is checked against the surface's faces at
/// the input places, the moved vertices as new ones (check_harm()'s `moves`).
struct HarmReference {
    std::span<const Vec3> input_positions;
    std::span<const std::uint8_t> moved;
    /// Gives up the moves of the corners of `faces` (harmful faces that hold no point): puts
    /// those vertices back at their input places in the surface being split, clears their
    /// flags in `moved` and makes the surface's normals around them again; gives the vertices
    /// put back, ascending.
    std::function<std::vector<Index>(const std::vector<Index>& faces)> give_up_moves;
};

/// Takes the surface to split, its bands and the feature normals (#V) to place points with, and
/// optionally the surface to check the split against (null: `input` itself). With a
/// reference, harm on faces that hold no point is the moves': their moves are given up
/// (`give_up_moves`), and the rounds go on, the faces within three rings of the vertices put
/// back guarded and checked again (guard_points_again()'s `reshaped`). The points stay as
/// placed on the moved places: each is judged anew where it lies.
/// \throws Cancelled when options.stop fires between two rounds; InvalidInput for options out
///         of range.
BandRestoration restore_bands(const InputSurface& input, const BandClassification& bands,
                              const FeatureNormals& feature_normals, const RestoreOptions& options,
                              const HarmReference* reference = nullptr);

}  // namespace resharp
