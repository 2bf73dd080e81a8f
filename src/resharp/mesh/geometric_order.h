#pragma once
/// Orders that depend on where vertices lie, not on how the mesh numbers them: the segmentations
/// take their decisions in these orders, and ties elsewhere are broken by them, so renumbering
/// the vertices, reordering the faces or rotating a face's corners gives the same restoration
/// (issue 12).

#include <algorithm>
#include <span>

#include "resharp/core/types.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

/// Lexicographic in (x, y, z): local ties (which of a few neighbours, which diagonal). A
/// similarity transform with positive scale keeps it, up to points its rounding makes equal.
inline bool lexicographically_less(const Vec3& a, const Vec3& b) {
    if (a.x() != b.x()) return a.x() < b.x();
    if (a.y() != b.y()) return a.y() < b.y();
    return a.z() < b.z();
}

/// Lexicographic in (z, y, x): the order in which a mesher sweeping its grid slab by slab meets
/// points, for decisions taken one after another across the part (which broken edge is bridged
/// first, which patch wins a tie of votes). Taken in this order they fall as they did in a
/// mesher's own numbering; with the ends of broken edges in (x, y, z) order the 3-cell cone of
/// smooth_solids_test got 86 phantom points where its bound allows 85.
inline bool sweep_less(const Vec3& a, const Vec3& b) {
    if (a.z() != b.z()) return a.z() < b.z();
    if (a.y() != b.y()) return a.y() < b.y();
    return a.x() < b.x();
}

/// Vertices ordered by position; coincident vertices by index (the only order they have).
inline bool vertex_before(const Mesh& mesh, Index a, Index b) {
    const Vec3 &pa = mesh.positions[a], &pb = mesh.positions[b];
    return pa != pb ? lexicographically_less(pa, pb) : a < b;
}

/// Vertices in sweep_less() order; coincident vertices by index.
inline bool vertex_swept_before(const Mesh& mesh, Index a, Index b) {
    const Vec3 &pa = mesh.positions[a], &pb = mesh.positions[b];
    return pa != pb ? sweep_less(pa, pb) : a < b;
}

/// Sorts vertex indices by vertex_before().
inline void sort_vertices(const Mesh& mesh, std::span<Index> vertices) {
    std::sort(vertices.begin(), vertices.end(),
              [&](Index a, Index b) { return vertex_before(mesh, a, b); });
}

}  // namespace resharp
