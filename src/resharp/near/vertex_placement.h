#pragma once
/// How a mesher placed a mesh's vertices, and on which grid, measured from the mesh alone
/// (issue 14 item 1). The near-surface restoration (near/vertex_moves.h) moves vertices only
/// when this says Near or Midpoint; Exact is the answer whenever the mesh does not show a grid.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "resharp/core/types.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

/// How the mesher placed the vertices (issue 14): on the surface (exact crossings, or bisection
/// to h/512, whose error is far below the method's tolerances), near it (one vertex per cell at
/// the mean of its crossings: surface nets, OpenVDB volumeToMesh), or at grid-edge midpoints.
enum class VertexPlacement : std::uint8_t { Exact, Near, Midpoint };

/// "exact", "near" or "midpoint".
std::string_view to_string(VertexPlacement placement);

/// The placement of a name to_string() gives, or nothing for any other name.
std::optional<VertexPlacement> vertex_placement_from_string(std::string_view name);

/// An axis-aligned grid: lines at origin + k * pitch on every axis (cubic cells).
struct Grid {
    double pitch = 0.0;          ///< h, in the mesh's units
    Vec3 origin = Vec3::Zero();  ///< a grid node; any node is as good (origin modulo pitch)
};

struct PlacementEstimate {
    VertexPlacement placement = VertexPlacement::Exact;
    std::optional<Grid> grid;  ///< the grid found (or the one given); none if it could not tell
    double on_grid_edge_share = 0.0;  ///< vertices with two coordinates on grid lines
    double midpoint_share = 0.0;      ///< of those, at the middle of their grid edge
    /// Triangles whose three vertices lie in three of the four cells around one grid edge, as
    /// every triangle of a surface-nets mesh does (0 when not measured).
    double dual_triangle_share = 0.0;
    /// The grid's pitch; when no grid fits, that of the best one tried (0: no spacing shows).
    double pitch = 0.0;
    std::string reason;  ///< one line for the report: what was measured
};

/// Takes a mesh (#V positions, #F triangles) and, optionally, the caller's grid (`given`, the
/// CLI's --grid), and gives how its vertices were placed and the grid, measured from the mesh
/// alone:
/// - grid lines show as coordinate values that many vertices share; the pitch is their common
///   spacing (a least-squares fit over all of them, so float32 rounding averages out) and the
///   origin a line value. It is first taken from the median gap between the values most
///   vertices share, and only where that gives no grid whose edges hold exactly placed vertices
///   searched for over a range of pitches (which costs most of the estimate);
/// - Midpoint: nearly every vertex has two coordinates on grid lines and the third at the middle
///   of its cell edge; on grid edges elsewhere (exact crossings, bisection): Exact;
/// - Near: few vertices on grid edges, but nearly every triangle spans three of the four cells
///   around one grid edge (the dual quads of surface nets, split in two);
/// - otherwise Exact, the path that never moves a vertex, with the reason.
/// `given` replaces the inferred grid. Coordinates compare within a few units in the last place
/// of the largest one (of float when every coordinate is a float, as in STL files). Linear in
/// #V and #F plus sorting the coordinates.
/// \throws InvalidInput if `given` has a pitch that is not positive and finite or an origin that
/// is not finite.
PlacementEstimate estimate_vertex_placement(const Mesh& mesh,
                                            const std::optional<Grid>& given = {});

}  // namespace resharp
