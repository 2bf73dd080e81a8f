#include "resharp/mesh/diagnostics.h"

#include <algorithm>

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

}  // namespace

std::vector<bool> find_degenerate_faces(const Mesh& mesh) {
    std::vector<bool> degenerate(mesh.face_count(), false);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) degenerate[f] = is_degenerate_face(mesh, f);
    return degenerate;
}

MeshDiagnostics diagnose(const Mesh& mesh, const Connectivity& c) {
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
    const DuplicateFaces duplicates = find_duplicate_faces(mesh, c);
    d.duplicate_faces = duplicates.removed + duplicates.opposite_pairs;

    DisjointSets sets(mesh.vertex_count());
    for (Index f = 0; f < mesh.face_count(); ++f) {
        d.degenerate_faces += is_degenerate_face(mesh, f);
        join_face(mesh, c, f, sets);
    }
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        const Index vi = static_cast<Index>(v);
        if (c.faces_around(vi).empty()) {
            ++d.isolated_vertices;
            continue;
        }
        if (sets.find(vi) == vi) ++d.components;
        if (is_nonmanifold_vertex(mesh, c, vi)) ++d.nonmanifold_vertices;
    }
    return d;
}

}  // namespace resharp
