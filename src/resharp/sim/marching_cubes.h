#pragma once
/// Meshing a tri-dexel grid (docs/design.md §4) on the grid whose cell edges lie on the dexel rays,
/// in the four ways grid meshers place their vertices, so that one simulation gives the test input
/// of each (docs/oracle.md):
/// - `mc`: marching cubes, every vertex at the exact ray crossing on its cell edge, so it lies on
///   the simulated surface and carries that surface's exact normal and id (the oracle);
/// - `bisect`: the same polygons, each vertex found by bisecting its cell edge on the
///   inside/outside state the dexel ray under it gives, as CAMotics does;
/// - `midpoint`: the same polygons, each vertex at its cell edge's midpoint (voxel carving);
/// - `surface-nets`: the dual of the marching-cubes polygons: one vertex per polygon (per cell,
///   or per surface piece of a cell) at the mean of its crossings, as OpenVDB's volumeToMesh
///   places them at adaptivity 0, and one quad per crossed cell edge, split along its shorter
///   diagonal.
///
/// How it decides, so that the mesh is closed, manifold and consistently oriented:
/// - a node's inside/outside state comes from the z-ray through it alone (one rule per node);
/// - a cell edge whose two nodes differ gets exactly one crossing, the end on its ray that bounds
///   the material around the inside node (an edge crossed three times keeps one; an edge crossed
///   twice has equal states and none: a feature thinner than h there is dropped, never torn);
/// - each cell's polygons are walked from per-face segments; a face with four crossings is
///   split by a rule that reads only that face's corners and crossings, so both cells agree.
///   The dual of these closed polygons is closed too: each crossed edge has one polygon in each
///   of its four cells.
/// If a ray disagrees with the z-ray state of a node (a surface within rounding of the node),
/// the nearest end on the ray is used, clamped onto the edge; MeshingStats counts these.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "resharp/mesh/mesh.h"
#include "resharp/sim/tridexel.h"

namespace resharp::sim {

/// How a cell face with four crossings (two inside corners on a diagonal) is split.
enum class AmbiguousFaceRule {
    ShorterCut,      ///< the pairing of crossings with the shorter total length; ties separate
    SeparateInside,  ///< always keep the two inside corners apart
};

/// Where a mesher puts its vertices (the header comment says how each works).
enum class Mesher {
    MarchingCubes,  ///< `mc`: on the exact ray crossing; the default
    Bisection,      ///< `bisect`: bisection along the cell edge, within h / 2^(steps + 1)
    Midpoint,       ///< `midpoint`: at the cell edge's midpoint, within h / 2
    SurfaceNets,    ///< `surface-nets`: one vertex per cell polygon, within its cell
};

/// "mc", "bisect", "midpoint" or "surface-nets".
const char* to_string(Mesher mesher);

/// The mesher of a name to_string() gives, or nothing for any other name.
std::optional<Mesher> mesher_from_string(std::string_view name);

struct MeshingOptions {
    Mesher mesher = Mesher::MarchingCubes;                              ///< see the enum
    AmbiguousFaceRule ambiguous_faces = AmbiguousFaceRule::ShorterCut;  ///< see the enum
    int bisection_steps = 8;  ///< halvings of a cell edge per vertex (Bisection), 1..52
    /// K: the triangles touching or crossing any of K grid planes x = const, spread evenly over
    /// the grid, are written a second time (appended), as the seams between the parallel jobs
    /// of CAMotics duplicate them. 0: none.
    int seam_duplicates = 0;
};

/// What the mesher met on the way.
struct MeshingStats {
    std::size_t ambiguous_faces = 0;       ///< cell faces with four crossings (counted per cell)
    std::size_t multiple_crossings = 0;    ///< crossed cell edges whose ray crosses them 3+ times
    std::size_t clamped_vertices = 0;      ///< vertices taken from the nearest end off their edge
    std::size_t duplicated_triangles = 0;  ///< triangles written twice on seams
};

/// A mesh with the exact data of every vertex. For a vertex off the surface (every mesher but
/// `mc`) the data are those of `surface_points`, the exact surface point taken as nearest it:
/// the foot of the vertex on the tangent plane of the exact crossing nearest it among those on
/// the edges of its cells (docs/oracle.md gives the error bound).
struct OracleMesh {
    Mesh mesh;  ///< outward-oriented, closed, manifold (unless seams are duplicated)
    std::vector<Vec3> surface_points;       ///< #V surface point nearest each vertex (mc: itself)
    std::vector<Vec3> normals;              ///< #V exact unit outward normals there
    std::vector<std::int32_t> surface_ids;  ///< #V ids of the surface there
    MeshingStats stats;
};

/// Meshes the material of `grid` with `options.mesher`. The grid's outermost nodes must be
/// outside the material (grid_enclosing() guarantees it for anything inside its box); otherwise
/// the mesh is open there. Deterministic: the same grid gives the same mesh on any thread count.
/// \throws InvalidInput if bisection_steps is not in 1..52 or seam_duplicates is negative or
/// more than the grid's interior node planes along x.
OracleMesh mesh_dexels(const DexelGrid& grid, const MeshingOptions& options = {});

}  // namespace resharp::sim
