#pragma once
/// Mesh validity of a restored mesh (docs/design.md §5): manifold, closed, oriented, flipped and
/// self-intersecting triangles, smallest angle.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "resharp/eval/ideal_points.h"
#include "resharp/eval/surface_samples.h"
#include "resharp/mesh/mesh.h"

namespace resharp::eval {

struct MeshValidity {
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::size_t boundary_edges = 0;      ///< edges with one face
    std::size_t nonmanifold_edges = 0;   ///< edges with three or more faces
    std::size_t inconsistent_edges = 0;  ///< edges whose two faces disagree on orientation
    std::size_t degenerate_faces = 0;    ///< repeated vertex or zero area
    std::size_t self_intersections = 0;  ///< intersecting face pairs (CGAL, exact predicates)
    double min_angle_deg = 0.0;          ///< smallest corner angle of a non-degenerate face
};

/// Counts the defects of `mesh`; the self-intersection test dominates the time.
MeshValidity check_validity(const Mesh& mesh);

/// Which faces count_flipped_faces judges.
enum class FlipScope {
    AllFaces,      ///< every face (the input as the mesher left it)
    ChangedFaces,  ///< faces not among the input's faces (pieces cut by restoration)
};

/// Faces turned against the surface they lie on: the face normal has a non-positive dot
/// product with the exact normal (`oracle`) of one of its input vertices, or, for a face of new
/// vertices only, turns more than 90 degrees against the normal of the exact sample nearest
/// its centroid. Where `exact` has samples, a face the vertex test finds turned is judged at its
/// centroid too, since a vertex on an edge carries one of its two surfaces' normals and a face
/// on the other surface meets it at the edge's angle; so is a face with an input vertex farther
/// than 1 % of the mean edge length from its oracle surface point (a midpoint or surface-nets
/// vertex; bisection's, h/512 off, are not), since an off-surface vertex beside an edge carries
/// the other face's normal. There it is flipped only if it turns more than 90 degrees against
/// every sample no farther than the nearest plus the largest such offset among its vertices
/// plus the samples' spacing: a mesh that far off the surface may lie that much nearer one face
/// of an edge than the other, and the surface point nearest it lie about a spacing from the
/// nearest sample, so a face on the top of a convex edge, overhanging its wall, is judged
/// against the top as well as the wall. Degenerate faces
/// are not counted. `output` starts with `input`'s vertices; pass input as output with
/// AllFaces to count the input's own flipped slivers.
/// \throws InvalidInput if the output does not start with the input's vertices or the oracle
/// does not have one normal per input vertex.
std::size_t count_flipped_faces(const Mesh& input, const Mesh& output, const Oracle& oracle,
                                const SurfaceSamples& exact, FlipScope scope);

/// As count_flipped_faces(), per output face (#F out): 1 where it is counted.
std::vector<std::uint8_t> flipped_faces(const Mesh& input, const Mesh& output, const Oracle& oracle,
                                        const SurfaceSamples& exact, FlipScope scope);

/// Output faces turned against the input surface they replace (issue 11's first harm test, here
/// measured apart from restore()'s own harm check and without its two-ring search): a face not
/// among the input's, or with a vertex moved, whose normal turns more than 90 degrees against
/// every input face nearest one of its query points (its centroid and its three vertices; faces
/// within a rounding tie of the nearest all count as nearest, so at an input vertex they are the
/// faces around it). Degenerate faces count. Output vertex i < #V in is input vertex i, moved or
/// not. Per output face (#F out): 1 where turned.
/// \throws InvalidInput if the output has fewer vertices than the input.
std::vector<std::uint8_t> turned_against_input(const Mesh& input, const Mesh& output);

}  // namespace resharp::eval
