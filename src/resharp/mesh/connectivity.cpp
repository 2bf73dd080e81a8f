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

/// A half-edge leaving a vertex, with its head, stored beside the vertex's ring so that finding
/// twins reads contiguous memory instead of hopping through the triangle array.
struct Outgoing {
    Index head;
    Index halfedge;
};

/// Per ring entry (aligned with ring_faces): the face's half-edge leaving the ring's vertex.
std::vector<Outgoing> outgoing_halfedges(const Mesh& mesh, const Connectivity& c) {
    std::vector<Outgoing> out(c.ring_faces.size());
    tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(mesh.vertex_count()), 4096),
                      [&](const auto& range) {
                          for (Index v = range.begin(); v != range.end(); ++v) {
                              for (Index i = c.ring_offsets[v]; i < c.ring_offsets[v + 1]; ++i) {
                                  const Index f = c.ring_faces[i];
                                  const Triangle& t = mesh.triangles[f];
                                  const Index k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
                                  out[i] = {t[(k + 1) % 3], 3 * f + k};
                              }
                          }
                      });
    return out;
}

/// Classifies every half-edge leaving `from`: its twins run from its head back to `from`, so
/// only the head's outgoing list needs a look; `from`'s own list tells whether another face
/// runs the same way. Rings are small, so this beats sorting all 3F half-edges by key.
void link_vertex(const Connectivity& c, const std::vector<Outgoing>& out, Index from,
                 std::vector<Index>& twin, std::vector<EdgeKind>& kind) {
    for (Index i = c.ring_offsets[from]; i < c.ring_offsets[from + 1]; ++i) {
        const auto [to, h] = out[i];
        if (to == from) {
            kind[h] = EdgeKind::NonManifold;  // a collapsed edge of a degenerate face
            continue;
        }
        Index opposite = kNoIndex;
        int opposite_count = 0;
        for (Index j = c.ring_offsets[to]; j < c.ring_offsets[to + 1]; ++j) {
            if (out[j].head == from) {
                opposite = out[j].halfedge;
                ++opposite_count;
            }
        }
        int same_direction_count = 0;
        for (Index j = c.ring_offsets[from]; j < c.ring_offsets[from + 1]; ++j) {
            same_direction_count += j != i && out[j].head == to;
        }
        const int sharing = 1 + opposite_count + same_direction_count;
        if (sharing == 1) {
            kind[h] = EdgeKind::Boundary;
        } else if (sharing > 2) {
            kind[h] = EdgeKind::NonManifold;
        } else if (same_direction_count == 1) {
            kind[h] = EdgeKind::Inconsistent;
        } else {
            kind[h] = EdgeKind::Manifold;
            twin[h] = opposite;
        }
    }
}

}  // namespace

Connectivity build_connectivity(const Mesh& mesh) {
    Connectivity c;
    build_rings(mesh, c);
    const std::size_t nh = 3 * mesh.face_count();
    c.twin.assign(nh, kNoIndex);
    c.edge_kind.assign(nh, EdgeKind::Boundary);
    const std::vector<Outgoing> out = outgoing_halfedges(mesh, c);
    tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(mesh.vertex_count()), 4096),
                      [&](const auto& range) {
                          for (Index v = range.begin(); v != range.end(); ++v) {
                              link_vertex(c, out, v, c.twin, c.edge_kind);
                          }
                      });
    return c;
}

}  // namespace resharp
