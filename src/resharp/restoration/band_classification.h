#pragma once
/// Combination of the two segmentations (paper §4, last paragraphs): which mesh edges cross a
/// chamfer band from one feature to another, and which triangles are edge or corner triangles.

#include <cstdint>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

enum class BandRole : std::uint8_t {
    None,    ///< not touched by restoration
    Edge,    ///< has a crossing edge: lies between two features (Fig. 7a)
    Corner,  ///< all three edges cross: lies among three features (Fig. 7b)
};

struct BandClassification {
    /// Per half-edge (#3F): 1 where the edge joins vertices of two different feature patches and
    /// touches an edge vertex; set on both half-edges of the edge.
    std::vector<std::uint8_t> is_crossing;
    std::vector<BandRole> face_role;  ///< per face (#F)
    std::size_t crossing_edges = 0;
    std::size_t edge_triangles = 0;    ///< faces with role Edge
    std::size_t corner_triangles = 0;  ///< faces with role Corner
};

/// Takes the connectivity, unit face normals (#F), the edge-vertex labels of segment_edges (#V)
/// and the vertex patches of segment_features (#V). Only manifold edges between two
/// non-degenerate faces can cross: boundary, non-manifold and degenerate parts are left as they
/// are.
BandClassification classify_bands(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const std::vector<std::uint8_t>& is_edge_vertex,
                                  const std::vector<Index>& vertex_patch);

}  // namespace resharp
