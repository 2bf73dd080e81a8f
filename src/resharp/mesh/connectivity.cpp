#include "resharp/mesh/connectivity.h"

#include <tbb/parallel_for.h>

namespace resharp {
namespace {

void build_rings(const Mesh& mesh, Connectivity& c) {
    const std::size_t nv = mesh.vertex_count();
    c.ring_offsets.assign(nv + 1, 0);
    for (const Triangle& t : mesh.triangles) {
        for (Index v : t) ++c.ring_offsets[v + 1];
    }
    for (std::size_t v = 0; v < nv; ++v) c.ring_offsets[v + 1] += c.ring_offsets[v];
    c.ring_faces.resize(c.ring_offsets[nv]);
    std::vector<Index> fill(c.ring_offsets.begin(), c.ring_offsets.end() - 1);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        for (Index v : mesh.triangles[f]) c.ring_faces[fill[v]++] = static_cast<Index>(f);
    }
}

/// Finds the twin of h by scanning the faces around its head vertex: rings are small, so this
/// beats sorting all 3F half-edges by key.
void link_halfedge(const Mesh& mesh, Connectivity& c, Index h) {
    const Index from = tail_vertex(mesh, h);
    const Index to = head_vertex(mesh, h);
    Index opposite = kNoIndex;
    int opposite_count = 0;
    int same_direction_count = 0;
    for (Index g : c.faces_around(to)) {
        for (Index k = 0; k < 3; ++k) {
            const Index candidate = 3 * g + k;
            if (candidate == h) continue;
            const Index a = tail_vertex(mesh, candidate);
            const Index b = head_vertex(mesh, candidate);
            if (a == to && b == from) {
                opposite = candidate;
                ++opposite_count;
            } else if (a == from && b == to) {
                ++same_direction_count;
            }
        }
    }
    const int sharing = 1 + opposite_count + same_direction_count;
    if (from == to) {
        c.edge_kind[h] = EdgeKind::NonManifold;  // a collapsed edge of a degenerate face
    } else if (sharing == 1) {
        c.edge_kind[h] = EdgeKind::Boundary;
    } else if (sharing > 2) {
        c.edge_kind[h] = EdgeKind::NonManifold;
    } else if (same_direction_count == 1) {
        c.edge_kind[h] = EdgeKind::Inconsistent;
    } else {
        c.edge_kind[h] = EdgeKind::Manifold;
        c.twin[h] = opposite;
    }
}

}  // namespace

Connectivity build_connectivity(const Mesh& mesh) {
    Connectivity c;
    build_rings(mesh, c);
    const std::size_t nh = 3 * mesh.face_count();
    c.twin.assign(nh, kNoIndex);
    c.edge_kind.assign(nh, EdgeKind::Boundary);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nh, 4096), [&](const auto& range) {
        for (std::size_t h = range.begin(); h != range.end(); ++h) {
            link_halfedge(mesh, c, static_cast<Index>(h));
        }
    });
    return c;
}

}  // namespace resharp
