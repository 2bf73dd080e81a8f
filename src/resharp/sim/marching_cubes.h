#pragma once
/// Marching cubes on a tri-dexel grid (design.md §4): the grid whose cell edges lie on the dexel
/// rays. Every mesh vertex is an interval end of the ray under its cell edge, so it lies exactly
/// on the simulated surface and carries that surface's exact normal and id (the oracle).
///
/// How it decides, so that the mesh is closed, manifold and consistently oriented:
/// - a node's inside/outside state comes from the z-ray through it alone (one rule per node);
/// - a cell edge whose two nodes differ gets exactly one vertex, the end on its ray that bounds
///   the material around the inside node (an edge crossed three times keeps one; an edge crossed
///   twice has equal states and none: a feature thinner than h there is dropped, never torn);
/// - each cell's polygons are walked from per-face segments; a face with four crossings is
///   split by a rule that reads only that face's corners and crossings, so both cells agree.
/// If a ray disagrees with the z-ray state of a node (a surface within rounding of the node),
/// the nearest end on the ray is used, clamped onto the edge; MeshingStats counts these.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "resharp/mesh/mesh.h"
#include "resharp/sim/tridexel.h"

namespace resharp::sim {

/// How a cell face with four crossings (two inside corners on a diagonal) is split.
enum class AmbiguousFaceRule {
    ShorterCut,      ///< the pairing of crossings with the shorter total length; ties separate
    SeparateInside,  ///< always keep the two inside corners apart
};

struct MeshingOptions {
    AmbiguousFaceRule ambiguous_faces = AmbiguousFaceRule::ShorterCut;  ///< see the enum
};

/// What the mesher met on the way.
struct MeshingStats {
    std::size_t ambiguous_faces = 0;     ///< cell faces with four crossings (counted per cell)
    std::size_t multiple_crossings = 0;  ///< crossed cell edges whose ray crosses them 3+ times
    std::size_t clamped_vertices = 0;    ///< vertices taken from the nearest end off their edge
};

/// A mesh with the exact data of every vertex.
struct OracleMesh {
    Mesh mesh;                              ///< outward-oriented, closed, manifold
    std::vector<Vec3> normals;              ///< #V exact unit outward normals
    std::vector<std::int32_t> surface_ids;  ///< #V ids of the surface each vertex lies on
    MeshingStats stats;
};

/// Meshes the material of `grid`. The grid's outermost nodes must be outside the material
/// (grid_enclosing() guarantees it for anything inside its box); otherwise the mesh is open
/// there. Deterministic: the same grid gives the same mesh on any thread count.
OracleMesh mesh_dexels(const DexelGrid& grid, const MeshingOptions& options = {});

}  // namespace resharp::sim
