#include "resharp/mesh/diagnostics.h"

#include <algorithm>

#include "resharp/core/disjoint_sets.h"
#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

/// True for the lowest-numbered half-edge of the undirected edge under h, so that an edge held by
/// several faces is counted once.
bool is_first_halfedge_of_edge(const Mesh& mesh, const Connectivity& c, Index h) {
    const Index a = tail_vertex(mesh, h);
    const Index b = head_vertex(mesh, h);
    for (Index g : c.faces_around(a)) {
        for (Index k = 0; k < 3; ++k) {
            const Index other = 3 * g + k;
            if (other >= h) continue;
            const Index x = tail_vertex(mesh, other);
            const Index y = head_vertex(mesh, other);
            if ((x == a && y == b) || (x == b && y == a)) return false;
        }
    }
    return true;
}

bool is_duplicate_of_earlier(const Mesh& mesh, const Connectivity& c, Index f) {
    Triangle sorted = mesh.triangles[f];
    std::sort(sorted.begin(), sorted.end());
    for (Index g : c.faces_around(mesh.triangles[f][0])) {
        if (g >= f) break;  // rings are in increasing face order
        Triangle other = mesh.triangles[g];
        std::sort(other.begin(), other.end());
        if (other == sorted) return true;
    }
    return false;
}

/// A vertex is manifold when its faces, linked through shared edges at the vertex, form one fan.
bool is_nonmanifold_vertex(const Mesh& mesh, const Connectivity& c, Index v) {
    const auto ring = c.faces_around(v);
    if (ring.size() < 2) return false;
    std::vector<bool> reached(ring.size(), false);
    std::vector<std::size_t> stack{0};
    reached[0] = true;
    std::size_t reached_count = 1;
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        const Triangle& t = mesh.triangles[ring[i]];
        for (std::size_t j = 0; j < ring.size(); ++j) {
            if (reached[j]) continue;
            const Triangle& u = mesh.triangles[ring[j]];
            // Two faces at v are linked when they share a second vertex besides v.
            bool linked = false;
            for (Index a : t) {
                if (a != v && std::find(u.begin(), u.end(), a) != u.end()) linked = true;
            }
            if (linked) {
                reached[j] = true;
                ++reached_count;
                stack.push_back(j);
            }
        }
    }
    return reached_count != ring.size();
}

}  // namespace

std::vector<bool> find_degenerate_faces(const Mesh& mesh) {
    std::vector<bool> degenerate(mesh.face_count(), false);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        degenerate[f] = t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
                        triangle_normal(mesh.positions[t[0]], mesh.positions[t[1]],
                                        mesh.positions[t[2]])
                            .isZero(0.0);
    }
    return degenerate;
}

MeshDiagnostics diagnose(const Mesh& mesh, const Connectivity& c) {
    MeshDiagnostics d;
    for (std::size_t h = 0; h < c.edge_kind.size(); ++h) {
        const Index hi = static_cast<Index>(h);
        if (tail_vertex(mesh, hi) == head_vertex(mesh, hi)) continue;  // degenerate face's edge
        switch (c.edge_kind[h]) {
            case EdgeKind::Boundary: ++d.boundary_edges; break;
            case EdgeKind::Inconsistent: d.inconsistent_edges += is_first_halfedge_of_edge(mesh, c, hi); break;
            case EdgeKind::NonManifold: d.nonmanifold_edges += is_first_halfedge_of_edge(mesh, c, hi); break;
            case EdgeKind::Manifold: break;
        }
    }

    const std::vector<bool> degenerate = find_degenerate_faces(mesh);
    d.degenerate_faces = static_cast<std::size_t>(std::count(degenerate.begin(), degenerate.end(), true));

    DisjointSets sets(mesh.vertex_count());
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        sets.unite(t[0], t[1]);
        sets.unite(t[1], t[2]);
        if (is_duplicate_of_earlier(mesh, c, static_cast<Index>(f))) ++d.duplicate_faces;
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
