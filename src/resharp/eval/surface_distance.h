#pragma once
/// Surface error of a mesh against the exact surface (docs/design.md §5): Chamfer and Hausdorff
/// distance, normal consistency, and on sharp features the Edge Chamfer Distance and Edge
/// F-score of Neural Dual Contouring (Chen et al. 2022; their evaluation script
/// eval_cd_nc_f1_ecd_ef1.py in github.com/czq142857/NDC).
///
/// NDC's definitions, as we apply them to two sample sets E (exact surface) and M (mesh):
/// - a sample is an *edge sample* when another sample of its own set within radius r has a
///   normal with |n . n'| < 0.2 (NDC: r = 0.004 on shapes in a unit box meshed on a 64^3 grid,
///   i.e. 0.256 h);
/// - ECD = mean over E's edge samples of the squared distance to the nearest edge sample of M,
///   plus the same from M to E; EF1 = F-score of those two nearest distances at threshold
///   0.005 (0.32 h); Chamfer (squared) likewise over all samples, F1 at 0.003 (0.192 h);
///   normal consistency = the mean of |n . n'| to the nearest sample, averaged over both ways.
/// Where we differ, and why: samples are ray-grid crossings (surface_samples.h), not random, so
/// the edge radius must exceed the sample pitch and defaults to 0.5 h (twice our default pitch
/// of h/4); distances from E are exact point-to-triangle distances to the mesh (NDC samples the
/// mesh), distances from M go to the nearest exact sample (an upper bound on the distance to
/// the exact surface, exact where the mesh lies on it). A second edge criterion, a dihedral
/// angle (n . n' < cos theta), also counts edges that are not near right angles.

#include <cstddef>

#include "resharp/eval/surface_samples.h"
#include "resharp/mesh/mesh.h"

namespace resharp::eval {

struct SurfaceMetricsOptions {
    double pitch = 0.5;               ///< h, mm: the unit of every length below
    double edge_radius = 0.5;         ///< r of the edge-sample test, in h (NDC: 0.256 h)
    double edge_max_abs_dot = 0.2;    ///< NDC edge sample: a neighbour with |n . n'| below
    double edge_dihedral_deg = 30.0;  ///< dihedral variant: a neighbour more than this apart
    double f1_threshold = 0.192;      ///< F1 distance threshold, in h (NDC: 0.003)
    double edge_f1_threshold = 0.32;  ///< EF1 distance threshold, in h (NDC: 0.005)
    double cell = 1.0;                ///< cell of the search grids, in h
};

/// Edge Chamfer Distance and Edge F-score for one edge criterion.
struct EdgeMetrics {
    std::size_t exact_edge_samples = 0;
    std::size_t mesh_edge_samples = 0;
    double ecd = 0.0;  ///< mm^2, sum of the two mean squared distances (NaN if M has none)
    double ef1 = 0.0;  ///< 0..1 (1 when E has no edge samples, as NDC)
};

struct SurfaceMetrics {
    std::size_t exact_samples = 0;
    std::size_t mesh_samples = 0;
    double chamfer_l1 = 0.0;          ///< mm, mean of the two mean distances
    double chamfer_l2 = 0.0;          ///< mm^2, sum of the two mean squared distances (NDC's CD)
    double hausdorff = 0.0;           ///< mm, largest distance either way
    double hausdorff_p99 = 0.0;       ///< mm, 99th percentile of all distances of both ways
    double normal_consistency = 0.0;  ///< 0..1, mean |n . n'| averaged over both ways
    double f1 = 0.0;                  ///< 0..1, F-score at f1_threshold
    EdgeMetrics edges_ndc;            ///< edge samples by |n . n'| < edge_max_abs_dot
    EdgeMetrics edges_dihedral;       ///< edge samples by dihedral angle > edge_dihedral_deg
};

/// Compares `mesh` (sampled as `mesh_samples`, see sample_mesh) with the exact surface
/// (`exact`, see sample_exact_surface). Runs on all cores.
/// \throws InvalidInput if either sample set is empty, a normals array does not match its
/// points, or an option is not positive.
SurfaceMetrics compare_surfaces(const Mesh& mesh, const SurfaceSamples& mesh_samples,
                                const SurfaceSamples& exact,
                                const SurfaceMetricsOptions& options = {});

}  // namespace resharp::eval
