#pragma once
/// The do-no-harm check: after the split, every output face that replaced an input face is held
/// against the input surface it replaces. It reads the input and the split mesh and says which
/// input faces' pieces do harm; undoing them is the pipeline's (restore()).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "resharp/restoration/input_surface.h"
#include "resharp/restoration/split.h"

namespace resharp {

struct HarmCheckOptions {
    /// Two adjacent output faces whose normals differ by more than this (degrees) are folded,
    /// unless the input faces they replace already differed by as much.
    double fold_angle_deg = 150.0;
    /// Test every piece against the faces near it for crossings (the most costly of the three
    /// checks).
    bool check_crossings = true;
    /// The turned check (a) also weighs the input faces beyond the two rings that may come as
    /// near a piece as its own face (the other side of a thin wall), as the tests and the
    /// evaluation do: per round, a pass over the input's faces for every 131,072 judged faces,
    /// and one more where a face beyond the rings turns against a piece. restore() asks it on
    /// near-surface and midpoint meshes, whose moves and points came nearer a thin wall's or
    /// blade's other side; on exact meshes it changed no output of the corpus and cost up to a
    /// fifth of restore() (impeller's harm check 20 -> 42 ms).
    bool beyond_rings = false;
};

struct HarmReport {
    /// Pieces turned more than 90 degrees against every input face nearest their centroid or
    /// one of their vertices (searched within two rings of their source face, or with
    /// HarmCheckOptions::beyond_rings over the whole input), or of no area.
    std::size_t turned = 0;
    std::size_t folded = 0;    ///< pieces folded onto an adjacent output face
    std::size_t crossing = 0;  ///< pieces meeting, or coming within rounding of, a nearby face
    /// The input faces whose pieces do harm, ascending: the faces to leave unsplit.
    std::vector<Index> harmful_faces;

    bool is_harmless() const { return harmful_faces.empty(); }
};

/// Near-surface restoration's moves (near/vertex_moves.h), as check_harm() reads them: the
/// surface it is given is the moved one, and these say where its vertices were in the input.
struct MovedVertices {
    /// Per input vertex (#V): its place in the split is not its input place. Empty: none moved.
    std::span<const std::uint8_t> moved;
    /// Per input vertex (#V), given with `moved`: its input place.
    std::span<const Vec3> input_positions;
};

/// Takes the input surface and its split; checks the pieces of every split face, the faces
/// the split lists as altered (faces left whole are the input's own and are not judged).
/// Near-surface restoration splits the input with vertices moved (near/vertex_moves.h): it
/// passes the moved surface (its mesh, connectivity and normals) as `input`, and `moves`: the
/// vertices whose place in the split is not their input place count as new vertices, and every
/// face with one as a split face, judged against the input surface it replaces. That surface
/// is the moved one's faces at the input places: a face with no moved corner has the moved
/// surface's normal, the same bits, and the split faces' input normals are made again from
/// their input corners (surface_normals()'s bits). No copy of the input mesh or its normals is
/// needed beside the moved one's (4 and 8 MB on mech by surface nets).
/// A fault between a piece and another split face's piece blames both faces.
///
/// The crossing check (c) tests a piece against the output faces of the input faces within two
/// rings of its own whose boxes meet the pieces' box, pairs sharing an edge left to the fold
/// check (b). Two kinds of pair are settled without the intersection test (triangles_meet()):
/// - pairs sharing only a vertex around which the output is a simple fan (simple_fan.h): they
///   cannot cross, by the fan's exact sectors rather than the test's tolerance (a pair of such
///   faces closer than the tolerance but apart is accepted where the test would have refused);
/// - pairs sharing no vertex that a plane through an edge of one, holding its normal, parts by
///   more than the tolerance (the separating axes the test itself would reach last).
/// On the benchmark parts this changes no verdict.
///
/// The turned check (a) weighs the input faces within two rings and, with
/// HarmCheckOptions::beyond_rings, found by one pass over the input's faces, those beyond that
/// turn against a piece and may come as near it as its own face (the other side of a thin wall).
///
/// A later round may pass `changed` (#F): the input faces whose pieces differ from those of an
/// earlier split this check judged, every face it found harmful among them. Then only the split
/// faces within two rings of a changed face are judged: a face's verdict depends on nothing but
/// its own pieces, those of the faces within two rings of it and the input faces (the same in
/// every round), so elsewhere it stands (no harm). The counts then cover the judged faces alone.
/// Empty: every split face is judged.
/// \throws InvalidInput if the fold angle is not in (90, 180], `changed` is neither empty nor
///         one flag per input face, or `moves` neither empty nor one flag and one input place
///         per input vertex.
HarmReport check_harm(const InputSurface& input, const SplitMesh& output,
                      const HarmCheckOptions& options = {},
                      std::span<const std::uint8_t> changed = {}, const MovedVertices& moves = {});

}  // namespace resharp
