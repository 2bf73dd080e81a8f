#include "resharp/mesh/diagnostics.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <functional>

#include "resharp/core/disjoint_sets.h"
#include "resharp/mesh/duplicate_faces.h"
#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

/// The number of distinct undirected edges among the half-edges `halfedges` (as vertex pairs),
/// by sorting: rings can be huge on collapsed meshes, where searching them would be quadratic.
std::size_t distinct_edges(const Mesh& mesh, const std::vector<Index>& halfedges) {
    std::vector<std::pair<Index, Index>> edges;
    edges.reserve(halfedges.size());
    for (Index h : halfedges) {
        const Index a = tail_vertex(mesh, h), b = head_vertex(mesh, h);
        edges.emplace_back(std::min(a, b), std::max(a, b));
    }
    std::sort(edges.begin(), edges.end());
    return static_cast<std::size_t>(std::unique(edges.begin(), edges.end()) - edges.begin());
}

/// A vertex is manifold when its faces form one fan: turning around it from one face across
/// manifold edges, forwards and then backwards, reaches every face of its ring.
bool is_nonmanifold_vertex(const Mesh& mesh, const Connectivity& c, Index v) {
    const auto ring = c.faces_around(v);
    if (ring.size() < 2) return false;
    const Triangle& t = mesh.triangles[ring[0]];
    const Index first = 3 * ring[0] + (t[0] == v ? 0 : t[1] == v ? 1 : 2);  // leaves v
    std::size_t reached = 1;
    Index h = first;
    // Bound: each turn reaches one more face, and more turns than the ring has faces end both
    // loops.
    for (;;) {  // forwards: across the edge entering v
        const Index twin = c.twin[prev_halfedge(h)];
        if (twin == kNoIndex) break;
        h = twin;
        if (h == first) return reached != ring.size();  // closed fan
        if (++reached > ring.size()) return true;
    }
    for (h = first;;) {  // backwards: across the edge leaving v
        const Index twin = c.twin[h];
        if (twin == kNoIndex) break;
        h = next_halfedge(twin);
        if (++reached > ring.size()) return true;
    }
    return reached != ring.size();
}

bool is_degenerate_face(const Mesh& mesh, std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
    const Vec3& a = mesh.positions[t[0]];
    const Vec3 n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    return n.x() == 0.0 && n.y() == 0.0 && n.z() == 0.0;
}

/// Puts the vertices of face f into one set. An edge whose twin lies in an earlier face needs no
/// union: that face already joined all of its vertices, both ends of the edge among them. On a
/// closed mesh this skips half the unions, each two finds through scattered memory.
void join_face(const Mesh& mesh, const Connectivity& c, Index f, DisjointSets& sets) {
    const Triangle& t = mesh.triangles[f];
    for (Index k = 0; k < 2; ++k) {
        const Index twin = c.twin[3 * f + k];
        if (twin == kNoIndex || face_of(twin) > f) sets.unite(t[k], t[k + 1]);
    }
}

/// The connected components of the faces' vertices (isolated vertices not counted).
std::size_t count_components(const Mesh& mesh, const Connectivity& c) {
    DisjointSets sets(mesh.vertex_count());
    for (Index f = 0; f < mesh.face_count(); ++f) join_face(mesh, c, f, sets);
    std::size_t components = 0;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
        components += !c.faces_around(v).empty() && sets.find(v) == v;
    }
    return components;
}

/// Degenerate faces, isolated and non-manifold vertices, counted in parallel (integer sums:
/// the same whatever the split).
void count_faces_and_vertices(const Mesh& mesh, const Connectivity& c, MeshDiagnostics& d) {
    using Range = tbb::blocked_range<Index>;
    d.degenerate_faces = tbb::parallel_reduce(
        Range(0, static_cast<Index>(mesh.face_count()), 4096), std::size_t{0},
        [&](const Range& r, std::size_t n) {
            for (Index f = r.begin(); f != r.end(); ++f) n += is_degenerate_face(mesh, f);
            return n;
        },
        std::plus<>());
    struct VertexCounts {
        std::size_t isolated = 0, nonmanifold = 0;
    };
    const VertexCounts counts = tbb::parallel_reduce(
        Range(0, static_cast<Index>(mesh.vertex_count()), 4096), VertexCounts{},
        [&](const Range& r, VertexCounts n) {
            for (Index v = r.begin(); v != r.end(); ++v) {
                if (c.faces_around(v).empty()) {
                    ++n.isolated;
                } else {
                    n.nonmanifold += is_nonmanifold_vertex(mesh, c, v);
                }
            }
            return n;
        },
        [](VertexCounts a, const VertexCounts& b) {
            return VertexCounts{a.isolated + b.isolated, a.nonmanifold + b.nonmanifold};
        });
    d.isolated_vertices = counts.isolated;
    d.nonmanifold_vertices = counts.nonmanifold;
}

}  // namespace

std::vector<bool> find_degenerate_faces(const Mesh& mesh) {
    std::vector<bool> degenerate(mesh.face_count(), false);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) degenerate[f] = is_degenerate_face(mesh, f);
    return degenerate;
}

MeshDiagnostics diagnose(const Mesh& mesh, const Connectivity& c) {
    return diagnose(mesh, c, find_duplicate_faces(mesh, c));
}

MeshDiagnostics diagnose(const Mesh& mesh, const Connectivity& c,
                         const DuplicateFaces& duplicates) {
    MeshDiagnostics d;
    std::vector<Index> inconsistent, nonmanifold;
    for_each_halfedge_without_twin(c, [&](Index h) {
        if (tail_vertex(mesh, h) == head_vertex(mesh, h)) return;  // degenerate face's edge
        switch (c.edge_kind[h]) {
            case EdgeKind::Boundary:
                ++d.boundary_edges;
                break;
            case EdgeKind::Inconsistent:
                inconsistent.push_back(h);
                break;
            case EdgeKind::NonManifold:
                nonmanifold.push_back(h);
                break;
            case EdgeKind::Manifold:
                break;
        }
    });
    d.inconsistent_edges = distinct_edges(mesh, inconsistent);
    d.nonmanifold_edges = distinct_edges(mesh, nonmanifold);
    d.duplicate_faces = duplicates.removed + duplicates.opposite_pairs;

    // The components (a union-find, serial) beside the per-face and per-vertex counts.
    tbb::parallel_invoke([&] { d.components = count_components(mesh, c); },
                         [&] { count_faces_and_vertices(mesh, c, d); });
    return d;
}

}  // namespace resharp
