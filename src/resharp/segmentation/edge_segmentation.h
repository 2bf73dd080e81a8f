#pragma once
/// Edge-based segmentation (paper §3): every vertex is labelled edge or non-edge by 2-means
/// clustering of its principal curvatures, then refined as Huang & Ascher (2008) do: isolated
/// edge vertices are dropped, broken edges are bridged, and edge vertices whose one-ring is
/// flat are sent back to non-edge.

#include <cstdint>
#include <vector>

#include "resharp/curvature/local_height.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

/// What k-means clusters per vertex.
enum class CurvatureFeature {
    /// (k1, k2) as the paper does (eq. 3.1). Convex edges sit at (0, +k) and concave ones at
    /// (-k, 0), so a single edge centre pulled towards the commoner kind can miss the other.
    Signed,
    /// (min(|k1|, |k2|), max(|k1|, |k2|)): convex and concave edges fall together.
    Magnitude,
};

struct EdgeSegmentationOptions {
    /// The clustered quantity; Signed is the paper's variant.
    CurvatureFeature feature = CurvatureFeature::Magnitude;
    /// eps_K, eq. 3.2: k-means stops when both centres move less than this (1/length).
    double kmeans_tolerance = 1e-5;
    /// Safety bound on k-means iterations; the paper's criterion normally stops far earlier.
    int max_kmeans_iterations = 200;
    /// P, §3.3: how many non-edge vertices a walk may visit to bridge a broken edge.
    int max_bridge_walk = 25;
    /// §3.3: an edge vertex whose one-ring face normals all lie within this angle of each
    /// other (degrees) is on a flat region and goes back to non-edge.
    double flat_normal_spread_deg = 10.0;
};

struct EdgeSegmentation {
    std::vector<std::uint8_t> is_edge;        ///< per vertex (#V): 1 for edge vertices
    std::size_t clustered_edge_vertices = 0;  ///< edge vertices straight out of k-means
    std::size_t isolated_removed = 0;         ///< edge vertices with no edge neighbour
    std::size_t bridge_vertices_added = 0;    ///< non-edge vertices made edge to join pieces
    std::size_t flat_removed = 0;             ///< edge vertices with a flat one-ring
    int kmeans_iterations = 0;

    std::size_t edge_vertex_count() const;
};

/// Takes the mesh, its connectivity, curvatures from estimate_principal_curvatures and unit
/// face normals (#F); gives the refined labels and what each refinement step changed.
/// \throws InvalidInput if an option is out of range.
EdgeSegmentation segment_edges(const Mesh& mesh, const Connectivity& connectivity,
                               const PrincipalCurvatures& curvatures,
                               const std::vector<Vec3>& face_normals,
                               const EdgeSegmentationOptions& options = {});

}  // namespace resharp
