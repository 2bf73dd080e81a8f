#pragma once
/// Near-surface restoration, its first half (issue 14): where the mesher left the vertices near
/// the surface rather than on it, each vertex is moved onto the surface of its feature patch as
/// the patch's own vertices around it show that surface (a fitted plane), and only within what
/// its mesher could have got wrong: a midpoint vertex along its own grid edge (the true crossing
/// lies on that edge), a cell-mean vertex within its own cell (within the cells around it where
/// the surface does not cross its own: there the mesher got it wrong by more). A band vertex goes
/// onto the side of its own patch, where that side is part of the solid's boundary next to the
/// other sides around it; the exact method of the paper then restores the band between the sides,
/// its vertices now on them.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/mesh/mesh.h"
#include "resharp/near/vertex_placement.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/input_surface.h"
#include "resharp/restoration/split.h"

namespace resharp {

struct VertexMoveOptions {
    /// Rings of neighbours searched for a patch's vertices to fit its plane to (at most 64).
    int fit_rings = 3;
    /// Near: the same for a band vertex's other sides where none has a plane within fit_rings,
    /// and for a junction's planes that have none there (at most 160 vertices). Off the grid axes a
    /// band winds two or three faces wide, so within three rings a band vertex often has fewer than
    /// min_fit_points of the other side's vertices off the band, and no plane to tell which part of
    /// its own plane bounds the solid. Its own plane, which it moves onto, is always fitted within
    /// fit_rings: on a curved patch a plane fitted this wide leaves the surface (spool lost 0.3 of
    /// its Edge F-score); fitted this wide where it has none nearby, it leads only onto a
    /// junction of flat sides.
    int other_side_fit_rings = 5;
    /// A patch with fewer vertices than this in reach gets no plane there.
    int min_fit_points = 6;
    /// A fit whose points scatter about it by more (root mean square, in grid pitches) is not
    /// taken for a plane: a curved patch, or one that took in part of another. Cell means of
    /// crossings on a plane lie on it; midpoints scatter along their grid edges by up to half a
    /// pitch (rms pitch / sqrt(12) where the plane runs across the edges).
    double max_scatter_near = 0.1;
    double max_scatter_midpoint = 0.35;
    /// A near vertex that segmentation left in a band with no patch of its own (the middle row
    /// of a band two faces wide, as surface nets leave one in the cell a sharp edge crosses)
    /// moves onto the junction of the planes of the two or three patches around it only where
    /// each two of them part by more than this (degrees): a junction of planes this far apart
    /// is a sharp edge or corner, not one face split in two by segmentation.
    double junction_angle_deg = 20.0;
    /// ... and only where the vertices of each of those patches scatter about its plane by at
    /// most this (root mean square, in grid pitches). Cell means of crossings on a plane lie on
    /// it to rounding; a fit that scatters more took in vertices off its face (a hole's rim),
    /// and two such planes meet off the true edge by their error over the sine of their angle
    /// (on the pocketed block of the tests, 0.02 to 0.1 pitch against 0 for the rest).
    double max_junction_scatter = 0.01;
};

struct VertexMoves {
    std::vector<Vec3> position;       ///< #V: where each vertex goes; its input position if not
    std::vector<std::uint8_t> moved;  ///< #V: 1 where position differs from the input's
    std::size_t moved_count = 0;
    double largest_move = 0.0;  ///< mm, from the input position
    /// Near: the vertices that go onto another patch's face (band vertices whose own side gives
    /// them no point, vertices between patches in the empty corner of a concave edge), with
    /// that patch; sorted by vertex. The moved mesh is segmented with them in it
    /// (patches_after_moves()).
    std::vector<std::pair<Index, Index>> onto_other_patch;
};

/// Where the planes a vertex moves onto come from.
enum class FitScope : std::uint8_t {
    /// The feature patches around the vertex, a plane each: its own, and for a band vertex its
    /// neighbours' (meshes whose segmentation found their faces).
    Patches,
    /// Every vertex within reach, one plane, taken only where they scatter about it as one
    /// face's would (midpoint meshes, whose stair-stepped slanted faces segmentation breaks into
    /// a patch per tread).
    Neighbourhood,
};

/// How vertices may move.
struct MoveRule {
    VertexPlacement placement = VertexPlacement::Exact;
    Grid grid;  ///< the grid the mesher placed the vertices on
    FitScope scope = FitScope::Patches;
};

/// Takes the mesh as it stands (`current`: positions, adjacency, normals), the input positions
/// it came from (#V: what each vertex may move away from, by the rule), the feature patch of
/// every vertex (#V, kNoIndex for none; Patches only) and the bands found (Patches only).
/// Near: a plane is fitted to a patch's vertices off the bands around the vertex; on a flat
/// face (most of the patch's vertices off the bands on one plane) it is the face's plane
/// wherever the fit scatters and half its points lie on that plane, or all lie within half a
/// pitch of it (the rest the mesher put off the face beside an edge; for a band vertex's own
/// side, in front of it only), and an exact fit to points that barely spread across it (a row
/// and a vertex) is none. Band vertices move by the shortest way onto the side of their own
/// patch, where it bounds the solid next to the other sides and within their input cell (within
/// the cells around where that side is a flat face's plane that misses the cell; the others lie
/// on their surface already, up to its curvature), or, where their own gives no such point,
/// onto another side's that does (VertexMoves::onto_other_patch); a vertex of no patch whose ring
/// meets two or three patches (those of its ring's vertices, or where they have fewer than two, of
/// the vertices within the fit rings: the two whose planes lie nearest it; a flat face whose
/// vertices there all lie in bands, its plane) moves onto where their
/// planes meet (the sharp edge or corner; not where its normal runs along an edge's line, on a
/// third face): the point of it nearest the vertex within its input
/// cell, or, where it misses that cell, the cell's point nearest it (where the vertex lies in
/// front of both of two planes, the empty corner of a concave edge, the junction's point nearest
/// it where that lies within two pitches in a cell that holds no input vertex in a band or
/// between patches, the vertex being
/// the nearest to it of those between patches in its ring and it out of their reach: the mesher
/// lost that cell, and the nearest vertex stands for it; else the nearer plane's point within
/// that reach, that plane's patch taken, VertexMoves::onto_other_patch); where
/// no plane crosses the
/// input cell (the mesher put the vertex where the surface is not, as OpenVDB does across a
/// concave corner, near/concave_bevels.h), within the cells around it too; three patches met
/// only beyond its ring give their corner where the vertex lies in front of all three and the
/// corner within that reach, else the two planes nearest it. A vertex of a flat face off the
/// bands moves onto the face's plane within its cell (the cells around where it misses that) only
/// where it lies in front of it (by at most half a pitch) and of another face within two
/// pitches (a curved one read as its tangent plane at its vertex off the bands nearest; the
/// empty corner of a concave edge, where OpenVDB displaces a face's rows). A vertex
/// off the bands on the border of two flat patches that lies behind both planes (a dual mesher's
/// vertex at a convex edge no band marks) goes where they meet within its cell, as a vertex of
/// no patch does. A band vertex of a patch beside one other, one of them curved, in the empty
/// corner of their concave edge (in front of both surfaces, the curved one fitted beyond the
/// rows OpenVDB displaces there, but not in front of the curved face's surface fitted nearby)
/// whose own side's point lies off its surface goes where the surfaces meet, likewise. A band
/// vertex of a patch that lies off its own plane goes instead onto where its sides' planes meet,
/// where that crosses its cell and every face around it then lies on one side: its two other
/// corners of one patch, or one of them on a junction too (the largest set of such vertices, which
/// does not depend on the order they are judged in). Midpoint: every vertex with a plane of its own
/// patch (or, Neighbourhood, around it) moves along its input grid edge onto it, within the edge
/// (short of its ends, the crossings around one grid node on a plane parallel to the face); a
/// patch whose vertices off the bands scatter about one plane as midpoints of one face's crossings
/// do has that plane, fitted to all of them (near a grid plane, where that leaves some beyond
/// their grid edges, the plane nearest it within every edge; its centroid, which tells which part
/// of it bounds the solid, that of its vertices near the vertex), and a vertex of no patch among
/// patches with planes (as a whole, or near it) goes where its grid edge meets the boundary their
/// planes make; a band vertex whose grid edge meets its own side's plane where that does not bound
/// the solid goes where it meets another side's that does; a vertex of a patch with no plane as a
/// whole whose vertices around lie on a bent face (a quadratic height over their plane fits them
/// within the midpoint scatter, curving by at most 1 / 3 h) goes where its grid edge meets that
/// height (Patches only). Exact: nothing moves. A vertex without a plane keeps its current
/// position. Each vertex is decided alone, from the inputs only: the same on any number of threads.
/// The result counts moves from the input positions. \throws InvalidInput if the grid's pitch is
/// not positive or an option is out of range.
VertexMoves plan_vertex_moves(const InputSurface& current, const std::vector<Vec3>& input,
                              const std::vector<Index>& vertex_patch,
                              const BandClassification& bands, const MoveRule& rule,
                              const VertexMoveOptions& options = {});

/// `vertex_patch` (#V) with every vertex that `moves` still moves onto another patch's face
/// (VertexMoves::onto_other_patch) in that patch: its crossing edges are then those to its own
/// patch's vertices, which the split cuts, and not those to the face it lies on.
std::vector<Index> patches_after_moves(std::vector<Index> vertex_patch, const VertexMoves& moves);

/// The mesh with every vertex at its planned position; faces as they were.
Mesh moved_mesh(const Mesh& mesh, const VertexMoves& moves);

/// `moves` with its flags and counts made again from its places against the input places
/// (#V): after some of its vertices were put back.
VertexMoves recounted(const std::vector<Vec3>& input, VertexMoves moves);

/// `moves` (of `mesh`, the input, with its connectivity) less the moves of the corners of every
/// face they turn over: its normal at the planned places against its input one, or no area. The
/// harm check refuses such a face as a rule, but only a round later (a move's harm ends a round
/// and the next restores anew: on mech by OpenVDB the four faces of its first round's moved
/// harm, and the second round made the restoration take twice the time). Repeated until no face
/// is turned over (a move taken back can turn a face beside it); a degenerate input face counts
/// for nothing. Bound: each pass but the last takes back a move.
VertexMoves without_turned_over_faces(const Mesh& mesh, const Connectivity& connectivity,
                                      VertexMoves moves);

}  // namespace resharp
