#include "resharp/mesh/connectivity.h"

#include <tbb/parallel_for.h>

#include "resharp/core/errors.h"

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

/// A half-edge filed under the lower of its two vertices: the other vertex, and the half-edge
/// with its top bit set when it runs from the lower vertex to the higher.
struct EdgeEntry {
    Index other;
    Index tagged_halfedge;
};
constexpr Index kForwardBit = Index{1} << 31;

/// Files every half-edge under its lower vertex (a counting sort): the half-edges of one edge
/// then sit side by side in a list of three or four entries, so finding twins reads contiguous
/// memory instead of hopping through the triangle array.
void file_halfedges(const Mesh& mesh, std::vector<Index>& offsets,
                    std::vector<EdgeEntry>& entries) {
    offsets.assign(mesh.vertex_count() + 1, 0);
    for (const Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) ++offsets[std::min(t[k], t[(k + 1) % 3]) + 1];
    }
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) offsets[v + 1] += offsets[v];
    entries.resize(offsets.back());
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        for (Index k = 0; k < 3; ++k) {
            const Index from = t[k], to = t[(k + 1) % 3];
            const Index low = std::min(from, to);
            entries[fill[low]++] = {std::max(from, to), (3 * f + k) | (from < to ? kForwardBit : 0)};
        }
    }
}

/// Classifies the half-edges filed under one vertex: those with the same other vertex lie on one
/// edge; exactly two running opposite ways are twins.
void link_edges_of(std::span<const EdgeEntry> filed, Index low, std::vector<Index>& twin,
                   std::vector<EdgeKind>& kind) {
    for (std::size_t i = 0; i < filed.size(); ++i) {
        const Index h = filed[i].tagged_halfedge & ~kForwardBit;
        if (filed[i].other == low) {
            kind[h] = EdgeKind::NonManifold;  // a collapsed edge of a degenerate face
            continue;
        }
        std::size_t sharing = 0, partner = i;
        for (std::size_t j = 0; j < filed.size(); ++j) {
            if (j == i || filed[j].other != filed[i].other) continue;
            ++sharing;
            partner = j;
        }
        if (sharing == 0) {
            kind[h] = EdgeKind::Boundary;
        } else if (sharing > 1) {
            kind[h] = EdgeKind::NonManifold;
        } else if ((filed[i].tagged_halfedge ^ filed[partner].tagged_halfedge) & kForwardBit) {
            kind[h] = EdgeKind::Manifold;
            twin[h] = filed[partner].tagged_halfedge & ~kForwardBit;
        } else {
            kind[h] = EdgeKind::Inconsistent;
        }
    }
}

}  // namespace

Connectivity build_connectivity(const Mesh& mesh) {
    if (mesh.face_count() >= kForwardBit / 3) {
        throw InvalidInput("meshes of more than " + std::to_string(kForwardBit / 3 - 1) +
                           " triangles are not supported");
    }
    Connectivity c;
    build_rings(mesh, c);
    const std::size_t nh = 3 * mesh.face_count();
    c.twin.assign(nh, kNoIndex);
    c.edge_kind.assign(nh, EdgeKind::Boundary);
    std::vector<Index> offsets;
    std::vector<EdgeEntry> entries;
    file_halfedges(mesh, offsets, entries);
    tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(mesh.vertex_count()), 4096),
                      [&](const auto& range) {
                          for (Index v = range.begin(); v != range.end(); ++v) {
                              const std::span<const EdgeEntry> filed(
                                  entries.data() + offsets[v], entries.data() + offsets[v + 1]);
                              link_edges_of(filed, v, c.twin, c.edge_kind);
                          }
                      });
    return c;
}

}  // namespace resharp
