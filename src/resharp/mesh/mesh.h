#pragma once
/// The two mesh containers: a triangle soup as files hold it, and the welded indexed mesh every
/// stage works on.

#include <vector>

#include "resharp/core/types.h"

namespace resharp {

/// Triangles as a file holds them. `triangles` index `points`; a position may appear several
/// times (STL stores three points per triangle), and nothing has been validated.
struct TriangleSoup {
    std::vector<Vec3> points;         ///< #P positions
    std::vector<Triangle> triangles;  ///< #T index triples into points
};

/// An indexed triangle mesh. After weld() no two vertices share a position, and every index is
/// below positions.size().
struct Mesh {
    std::vector<Vec3> positions;      ///< #V vertex positions
    std::vector<Triangle> triangles;  ///< #F counter-clockwise vertex triples (outward normals)

    std::size_t vertex_count() const { return positions.size(); }
    std::size_t face_count() const { return triangles.size(); }
};

/// A welded mesh and where each point of its soup went.
struct WeldedMesh {
    Mesh mesh;
    /// #P: the vertex of `mesh` each soup point became, kNoIndex for a point no triangle uses.
    std::vector<Index> vertex_of_point;
};

/// Merges points whose coordinates are exactly equal (bitwise, after folding -0 into +0) and
/// drops points no triangle uses. Vertices keep the order in which the triangles first use them.
/// \throws InvalidInput if an index is out of range or a coordinate is NaN or infinite.
WeldedMesh weld_mapped(const TriangleSoup& soup);

/// weld_mapped()'s mesh alone.
Mesh weld(const TriangleSoup& soup);

/// The mesh as a soup (positions and triangles unchanged), for writers that take soups.
TriangleSoup to_soup(const Mesh& mesh);

}  // namespace resharp
