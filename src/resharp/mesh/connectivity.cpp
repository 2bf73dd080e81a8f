#include "resharp/mesh/connectivity.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "resharp/core/assert.h"
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
    c.ring_faces.resize(c.ring_offsets[nv]);  // unwritten: the scatter below fills every entry
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

/// The half-edges filed under v, at the start of `filed` (grown as needed; never shrunk, so
/// that a vertex costs no allocation); gives their number. Every half-edge whose
/// lower vertex is v lies in a face of v's ring, so the ring (already sorted by face) yields
/// them without a second counting sort over all half-edges, and they sit side by side for the
/// twin search. All three edges of each face are looked at: testing them costs less than
/// finding v's corner, and a face with a repeated vertex needs all three anyway (in a face with
/// three distinct vertices only the two edges at v can be filed under it).
std::size_t file_halfedges_of(const Mesh& mesh, const Connectivity& c, Index v,
                              std::vector<EdgeEntry>& filed) {
    const auto ring = c.faces_around(v);
    if (filed.size() < 3 * ring.size()) filed.resize(3 * ring.size());  // the most it can file
    EdgeEntry* next = filed.data();
    auto file = [&](Index f, Index k, Index from, Index to) {
        if (std::min(from, to) == v) {
            *next++ = {std::max(from, to), (3 * f + k) | (from < to ? kForwardBit : 0)};
        }
    };
    Index previous = kNoIndex;
    for (Index f : ring) {
        if (f == previous) continue;  // a face using v twice is listed twice
        previous = f;
        const Triangle& t = mesh.triangles[f];
        file(f, 0, t[0], t[1]);
        file(f, 1, t[1], t[2]);
        file(f, 2, t[2], t[0]);
    }
    return static_cast<std::size_t>(next - filed.data());
}

/// Sorts the entries by their other vertex: insertion sort for the handful of a grid mesh's
/// vertex, std::sort for the long rings of collapsed meshes.
void sort_by_other(std::span<EdgeEntry> filed) {
    if (filed.size() > 16) {
        std::sort(filed.begin(), filed.end(),
                  [](const EdgeEntry& a, const EdgeEntry& b) { return a.other < b.other; });
        return;
    }
    for (std::size_t i = 1; i < filed.size(); ++i) {
        const EdgeEntry e = filed[i];
        std::size_t j = i;
        for (; j > 0 && filed[j - 1].other > e.other; --j) filed[j] = filed[j - 1];
        filed[j] = e;
    }
}

Index halfedge_of(const EdgeEntry& e) { return e.tagged_halfedge & ~kForwardBit; }

/// What the half-edges on one edge are, given all of them (same lower and other vertex).
EdgeKind kind_of_edge(std::span<const EdgeEntry> on_edge, Index low) {
    if (on_edge[0].other == low) return EdgeKind::NonManifold;  // collapsed: a degenerate face's
    switch (on_edge.size()) {
        case 1:
            return EdgeKind::Boundary;
        case 2:
            return (on_edge[0].tagged_halfedge ^ on_edge[1].tagged_halfedge) & kForwardBit
                       ? EdgeKind::Manifold
                       : EdgeKind::Inconsistent;
        default:
            return EdgeKind::NonManifold;
    }
}

/// Classifies the half-edges filed under one vertex: those with the same other vertex lie on one
/// edge; exactly two running opposite ways are twins. Writes the kind and the twin (kNoIndex
/// where none) of every one of them. Sorting the few entries by the other
/// vertex puts each edge's half-edges side by side, which costs fewer (and better predicted)
/// comparisons than counting every entry's partners among all the others.
void link_edges_of(std::span<EdgeEntry> filed, Index low, FilledLater<Index>& twin,
                   FilledLater<EdgeKind>& kind) {
    sort_by_other(filed);
    for (std::size_t first = 0, end = 0; first < filed.size(); first = end) {
        while (end < filed.size() && filed[end].other == filed[first].other) ++end;
        const std::span<const EdgeEntry> on_edge(filed.data() + first, end - first);
        const EdgeKind edge_kind = kind_of_edge(on_edge, low);
        if (edge_kind == EdgeKind::Manifold) {
            const Index a = halfedge_of(on_edge[0]), b = halfedge_of(on_edge[1]);
            kind[a] = kind[b] = EdgeKind::Manifold;
            twin[a] = b;
            twin[b] = a;
            continue;
        }
        for (const EdgeEntry& e : on_edge) {
            kind[halfedge_of(e)] = edge_kind;
            twin[halfedge_of(e)] = kNoIndex;
        }
    }
}

}  // namespace

namespace {

/// Invariant of the adjacency: twins are mutual, run the other way along the same edge, and
/// exist exactly on manifold edges.
[[maybe_unused]] bool has_symmetric_twins(const Mesh& mesh, const Connectivity& c) {
    for (Index h = 0; h < c.twin.size(); ++h) {
        const Index t = c.twin[h];
        if ((t != kNoIndex) != (c.edge_kind[h] == EdgeKind::Manifold)) return false;
        if (t == kNoIndex) continue;
        if (c.twin[t] != h || tail_vertex(mesh, t) != head_vertex(mesh, h) ||
            head_vertex(mesh, t) != tail_vertex(mesh, h)) {
            return false;
        }
    }
    return true;
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
    // Unwritten: every half-edge is filed under the lower of its two vertices (the face is in
    // that vertex's ring), and link_edges_of() writes its kind and twin there.
    c.twin.resize(nh);
    c.edge_kind.resize(nh);
    tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(mesh.vertex_count()), 4096),
                      [&](const auto& range) {
                          std::vector<EdgeEntry> filed;
                          for (Index v = range.begin(); v != range.end(); ++v) {
                              const std::size_t count = file_halfedges_of(mesh, c, v, filed);
                              link_edges_of({filed.data(), count}, v, c.twin, c.edge_kind);
                          }
                      });
    RESHARP_EXPENSIVE_ASSERT(has_symmetric_twins(mesh, c));
    return c;
}

std::vector<Index> faces_within_rings(const Mesh& mesh, const Connectivity& connectivity,
                                      std::vector<Index> vertices, int rings) {
    std::vector<std::uint8_t> reached_vertex(mesh.vertex_count(), 0);
    std::vector<std::uint8_t> reached_face(mesh.face_count(), 0);
    std::vector<Index> faces;
    for (Index v : vertices) reached_vertex[v] = 1;
    for (int ring = 0; ring < rings; ++ring) {
        std::vector<Index> next;
        for (Index v : vertices) {
            for (Index f : connectivity.faces_around(v)) {
                if (reached_face[f]) continue;
                reached_face[f] = 1;
                faces.push_back(f);
                for (Index w : mesh.triangles[f]) {
                    if (!reached_vertex[w]) next.push_back(w);
                    reached_vertex[w] = 1;
                }
            }
        }
        vertices = std::move(next);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

}  // namespace resharp
