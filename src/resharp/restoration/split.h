#pragma once
/// The split (paper §5.2, after Attene et al.'s EdgeSharpener): every accepted edge point is
/// inserted on its crossing edge and every corner point inside its corner triangle, and the
/// faces are re-triangulated (restoration/pieces.h) so that consecutive new points are joined
/// by mesh edges. The restored sharp edge is then a chain of mesh edges, a crease that viewers
/// show as one line. Tessellation only: which points are inserted, the guard decided.

#include <span>
#include <vector>

#include "resharp/mesh/mesh.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp {

struct SplitMesh {
    /// The input vertices first, unchanged and in order, then the points the slots use, in
    /// point order; each input face in order, either unchanged or replaced by its pieces.
    Mesh mesh;
    /// Per output face (#F out): the input face it is or was cut from; ascending.
    std::vector<Index> source_face;
    /// Per new vertex (output vertex input_vertices + i): its index in the points list.
    std::vector<Index> point_of_new_vertex;
    std::size_t split_faces = 0;  ///< input faces replaced by pieces
    /// The input faces whose output is not the input face itself, ascending: the faces replaced
    /// by pieces and, in a split made of moves (near/vertex_moves.h), the faces with a moved
    /// corner. Every other input face is one output face, its own. (So the harm check finds
    /// the faces it judges without comparing every output face with its source.)
    std::vector<Index> altered_faces;
};

/// Takes the input mesh, the points (#P) and the slots saying where each goes (as the guard
/// accepted them); gives the split mesh. Slots must only name points below #P.
SplitMesh split_faces(const Mesh& mesh, std::span<const Vec3> points, const PointSlots& slots);

}  // namespace resharp
