#pragma once
/// Combination of the two segmentations (paper §4, last paragraphs): which mesh edges cross a
/// chamfer band from one feature to another, and which triangles are edge or corner triangles.

#include <cstdint>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp {
class FeatureNormals;
}

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

struct ClassificationOptions {
    /// A border between two feature patches where neither vertex is an edge vertex still
    /// crosses a sharp edge when the two patches' normals there differ by more than this
    /// (degrees). Shallow transitions (a ball-end surface running into a flat face) bend too
    /// gently for the curvature clustering of §3 but are sharp edges all the same. 180 turns it
    /// off: the paper's combination, where only edge vertices confirm a border.
    /// 20 degrees lets the cusps between neighbouring ball-end passes count (their exact
    /// normals part by 30 degrees and more, the mean face normals on either side by less); smooth
    /// borders that merging left, between patches kept apart elsewhere, stay well below it.
    double unconfirmed_border_angle_deg = 20.0;
    /// A border whose patches' normals differ by less than this (degrees) is never a sharp
    /// edge, edge vertices or not. Merging joins borders this smooth, so only patches it kept
    /// apart (FeatureSegmentationOptions::keep_sharp_borders_apart) leave them, and the
    /// curvature of a ball-end surface can flag their vertices as edge vertices. 0 is the
    /// paper's rule.
    double smooth_border_angle_deg = 15.0;
    /// A crossing edge stays one only where the two sides' fitted normal fields
    /// (feature_normals()), each carried to the edge's midpoint, still part by more than this
    /// (degrees). On one smooth surface split into two patches (the facets of a cylinder a few
    /// cells in radius turn by some 20 degrees from one to the next) the two fields meet there,
    /// up to the roughness of the fits, however far the normal turns across the band; at a
    /// sharp edge they part by the edge's angle. 25 degrees left the benchmark parts' rates
    /// within 0.02 points (docs/method.md, "Smooth surfaces"). 0 keeps every crossing edge (the
    /// paper's rule).
    double smooth_continuation_angle_deg = 25.0;
};

/// Takes the connectivity, unit face normals (#F), the edge-vertex labels of segment_edges (#V)
/// and the face and vertex patches of segment_features (#F, #V). Only manifold edges between
/// two non-degenerate faces can cross: boundary, non-manifold and degenerate parts are left as
/// they are.
BandClassification classify_bands(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const std::vector<std::uint8_t>& is_edge_vertex,
                                  const std::vector<Index>& face_patch,
                                  const std::vector<Index>& vertex_patch,
                                  const ClassificationOptions& options = {});

/// Takes a classification of classify_bands() and the feature normals computed on it, and gives
/// the classification less the crossing edges whose two sides continue one smooth surface: the
/// normal fields of its two vertices (FeatureNormals::field; eq. 5.1's normal without a slope
/// where a vertex has none), each carried to the edge's midpoint, lie within
/// options.smooth_continuation_angle_deg. Edges with no normal at either end are kept.
BandClassification drop_smooth_crossings(const Mesh& mesh, const Connectivity& connectivity,
                                         const BandClassification& bands,
                                         const FeatureNormals& normals,
                                         const ClassificationOptions& options = {});

/// Takes per-half-edge crossing flags (#3F, set on both halves of each crossing edge, which must
/// be manifold) and gives the classification they make: a face with one or two crossing edges is
/// an edge triangle, with three a corner triangle. classify_bands() ends here; the evaluation
/// builds the oracle's classification the same way.
BandClassification classify_faces(std::vector<std::uint8_t> is_crossing);

/// Per vertex of `mesh` (#V): 1 where it is a corner of an edge or corner triangle of `bands`.
std::vector<std::uint8_t> band_vertices(const Mesh& mesh, const BandClassification& bands);

}  // namespace resharp
