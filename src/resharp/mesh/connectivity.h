#pragma once
/// Adjacency of an indexed triangle mesh: half-edge twins and vertex-to-face rings.
///
/// Half-edge h = 3f + k runs from triangles[f][k] to triangles[f][(k + 1) % 3]; its face is
/// h / 3. Rings are stored in CSR form (count, prefix sum, scatter) so building them allocates
/// three arrays and nothing per element.

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "resharp/core/filled_later.h"
#include "resharp/core/types.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

inline Index face_of(Index halfedge) { return halfedge / 3; }
inline Index next_halfedge(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
inline Index prev_halfedge(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }
inline Index tail_vertex(const Mesh& mesh, Index h) { return mesh.triangles[h / 3][h % 3]; }
inline Index head_vertex(const Mesh& mesh, Index h) {
    return mesh.triangles[h / 3][(h % 3 + 1) % 3];
}

/// What kind of edge a half-edge lies on.
enum class EdgeKind : unsigned char {
    Manifold,      ///< exactly one twin, running the other way
    Boundary,      ///< no other face has this edge
    NonManifold,   ///< three or more faces share the edge
    Inconsistent,  ///< two faces share it running the same way (orientation flips here)
};

struct Connectivity {
    /// Per half-edge (#3F): the twin half-edge, or kNoIndex unless edge_kind is Manifold.
    FilledLater<Index> twin;
    /// Per half-edge (#3F).
    FilledLater<EdgeKind> edge_kind;
    /// CSR offsets (#V + 1) into ring_faces.
    std::vector<Index> ring_offsets;
    /// Faces around each vertex (#3F in total), in increasing face order.
    FilledLater<Index> ring_faces;

    std::span<const Index> faces_around(Index v) const {
        return {ring_faces.data() + ring_offsets[v], ring_faces.data() + ring_offsets[v + 1]};
    }
};

/// Calls visit(j) for every vertex j != v that shares a face with v. A neighbour reached
/// through two faces is visited twice: callers that count must deduplicate.
template <class Visit>
void for_each_ring_vertex(const Mesh& mesh, const Connectivity& connectivity, Index v,
                          Visit&& visit) {
    for (Index f : connectivity.faces_around(v)) {
        for (Index j : mesh.triangles[f]) {
            if (j != v) visit(j);
        }
    }
}

/// Calls visit(h) for every half-edge h without a twin (edge kind not Manifold), ascending.
/// Almost every edge is manifold (kind 0), so eight kinds are read at a time and skipped
/// together.
template <class Visit>
void for_each_halfedge_without_twin(const Connectivity& connectivity, Visit&& visit) {
    static_assert(static_cast<unsigned>(EdgeKind::Manifold) == 0 && sizeof(EdgeKind) == 1);
    const auto& kind = connectivity.edge_kind;
    const Index count = static_cast<Index>(kind.size());
    Index h = 0;
    for (; h + 8 <= count; h += 8) {  // Bound: count / 8 words
        std::uint64_t eight = 0;
        std::memcpy(&eight, kind.data() + h, sizeof eight);
        if (eight == 0) continue;
        for (Index i = h; i < h + 8; ++i) {
            if (kind[i] != EdgeKind::Manifold) visit(i);
        }
    }
    for (; h < count; ++h) {
        if (kind[h] != EdgeKind::Manifold) visit(h);
    }
}

/// Builds twins and rings. Takes any mesh with valid indices; defects are classified in
/// edge_kind, never thrown. \throws InvalidInput for meshes of 2^31 / 3 triangles or more.
Connectivity build_connectivity(const Mesh& mesh);

/// The faces within `rings` rings of `vertices`, ascending: those around them, then those
/// around the corners of those, and so on. Bound: rings times the faces reached.
std::vector<Index> faces_within_rings(const Mesh& mesh, const Connectivity& connectivity,
                                      std::vector<Index> vertices, int rings);

}  // namespace resharp
