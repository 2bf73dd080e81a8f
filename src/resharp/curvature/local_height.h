#pragma once
/// Principal curvature estimates from local height intensity (Huang & Ascher 2008), as the
/// paper's edge-based segmentation uses them (paper §3.2).
///
/// For vertex i with unit normal n_i and ring neighbour j, the normal curvature along the
/// direction to j is about kappa_ij = -2 (x_j - x_i) . n_i / |x_j - x_i|^2 (positive where the
/// surface bends away from its outward normal, i.e. on convex parts). k1 and k2 are the smallest
/// and largest of these samples: only first-order information is used, so the estimate is cheap
/// and robust on the noise-free vertices a grid simulator makes.

#include <vector>

#include "resharp/core/filled_later.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

struct PrincipalCurvatures {
    FilledLater<double> k1;  ///< per vertex (#V): smallest normal curvature sample, 1/length
    FilledLater<double> k2;  ///< per vertex (#V): largest, k1 <= k2
};

/// Takes the mesh, its connectivity and unit vertex normals (#V, zero where undefined) and
/// gives k1 <= k2 per vertex; zero for vertices with no neighbour or no normal. Samples are
/// clamped to +-2 / (median edge length): a vertex whose neighbour sits at distance d from its
/// tangent plane cannot honestly claim more than 2 d / d^2, and degenerate slivers would
/// otherwise dominate the clustering that follows.
PrincipalCurvatures estimate_principal_curvatures(const Mesh& mesh,
                                                  const Connectivity& connectivity,
                                                  const std::vector<Vec3>& vertex_normals);

/// Median length of the mesh's edges (each half-edge counted), 0 for an empty mesh.
double median_edge_length(const Mesh& mesh);

}  // namespace resharp
