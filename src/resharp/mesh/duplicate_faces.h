#pragma once
/// Mesher artefacts among the faces: exact duplicates (the same three vertices in the same
/// cyclic order, as simulators write along their job seams) and pairs of opposite faces (the
/// same three vertices in opposite orders: a sheet of zero thickness).

#include <cstddef>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

struct DuplicateFaces {
    /// The faces to keep, ascending: every face but the later copies of an exact duplicate
    /// (the first copy stays). Empty when there is no duplicate.
    std::vector<Index> kept;
    std::size_t removed = 0;         ///< later copies of exact duplicates
    std::size_t opposite_pairs = 0;  ///< pairs of faces with opposite orders, kept
};

/// Takes a mesh and its connectivity. Exact duplicates share every edge with their copy, so
/// only faces with a non-manifold or inconsistent edge are compared: a clean mesh costs one
/// pass over its edge kinds. Faces with a repeated vertex are neither compared nor removed.
DuplicateFaces find_duplicate_faces(const Mesh& mesh, const Connectivity& connectivity);

/// The mesh with only the faces `kept` (ascending), in that order; vertices unchanged.
Mesh keep_faces(const Mesh& mesh, const std::vector<Index>& kept);

/// The faces drop_faces() took out of a mesh, to put back.
struct DroppedFaces {
    std::vector<Index> index;        ///< their places in the mesh, ascending
    std::vector<Triangle> triangle;  ///< per dropped face
};

/// keep_faces() in place, for a mesh whose owner gives it up: no second mesh is made. Takes
/// the faces to keep (ascending); gives the others.
DroppedFaces drop_faces(Mesh& mesh, const std::vector<Index>& kept);

/// Undoes drop_faces(): the dropped faces go back to their places.
void put_back_faces(Mesh& mesh, const DroppedFaces& dropped);

}  // namespace resharp
