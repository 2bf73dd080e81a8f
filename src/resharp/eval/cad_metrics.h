#pragma once
/// Measures of a mesh of a CAD-like part against its exact solid (issue 13, design.md §5): the
/// surface measures of surface_distance.h divided by the bounding-box diagonal, and on the sharp
/// edges the Edge Chamfer Distance and Edge F-score of Neural Dual Contouring (Chen et al. 2022)
/// between the true crease curves (exact_creases.h) and the mesh's sharp edges, with the ratio of
/// their lengths.
///
/// Where we follow NDC and where not: NDC finds edge samples in both point clouds by a normal
/// test among neighbours; here the true edges are the exact curves where two surfaces of the
/// solid meet at more than θ_s, and the mesh's are its edges whose two faces meet at more than
/// θ_s (30°). Both are sets of short straight pieces with a length each; every distance is from
/// a sample to the nearest piece of the other set, and every mean weighs the samples by length.
/// ECD = mean squared distance from true to mesh plus from mesh to true; EF1 = F-score of
/// precision (share of the mesh's crease length within τ of a true edge) and recall (share of
/// the true length within τ of a mesh crease), τ = 0.1 % of the diagonal. Distances are divided
/// by the diagonal before squaring.

#include <cstddef>
#include <vector>

#include "resharp/eval/surface_distance.h"
#include "resharp/mesh/mesh.h"

namespace resharp::eval {

/// Points along curves, each standing for the straight piece point ± half_span * tangent.
struct CurveSamples {
    std::vector<Vec3> points;        ///< #C
    std::vector<Vec3> tangents;      ///< #C unit tangents
    std::vector<double> weights;     ///< #C length of curve each sample stands for, mm
    std::vector<double> half_spans;  ///< #C half the length of its piece, mm
    /// #C for a mesh's creases (sample_mesh_creases()): the half-edge each piece lies on; empty
    /// for curves.
    std::vector<Index> half_edges;
    std::size_t size() const { return points.size(); }
    /// Sum of the weights, mm.
    double total_length() const;
};

/// The edges of `mesh` whose two faces' normals part by more than `sharp_angle_deg` (manifold
/// edges between non-degenerate faces only), cut into pieces no longer than `spacing` (mm): one
/// sample per piece at its middle, weight and span the piece's length.
/// \throws InvalidInput if spacing is not positive.
CurveSamples sample_mesh_creases(const Mesh& mesh, double sharp_angle_deg, double spacing);

/// Distance (mm) from every sample of `from` to the nearest piece of `to`; infinity for all
/// when `to` is empty. Runs on all cores.
std::vector<double> crease_distances(const CurveSamples& from, const CurveSamples& to);

struct CreaseMetricsOptions {
    double tolerance = 1e-3;  ///< τ of the Edge F-score, in units of `unit`
    double far = 1e-2;  ///< a mesh sharp edge this far from every true one is a stray, in `unit`
    double unit = 1.0;  ///< mm; every length and distance is divided by it (the diagonal)
};

/// Sharp edges of a mesh against the true ones. Lengths and distances in `unit`.
struct CreaseMetrics {
    std::size_t true_samples = 0, mesh_samples = 0;
    double true_length = 0.0;   ///< length of the true sharp edges
    double mesh_length = 0.0;   ///< length of the mesh's sharp edges
    double length_ratio = 0.0;  ///< mesh_length / true_length (NaN without true edges)
    /// Length of the mesh's sharp edges farther than `far` from every true one (creases where
    /// the part is smooth or flat), in unit.
    double stray_length = 0.0;
    /// Mean squared distance both ways, summed; 0 when neither has sharp edges, NaN when only
    /// one has.
    double ecd = 0.0;
    double precision = 1.0;  ///< share of mesh_length within τ of a true edge (1 if none)
    double recall = 1.0;     ///< share of true_length within τ of a mesh edge (1 if none)
    double ef1 = 1.0;        ///< F-score of the two (0 when only one side has sharp edges)
};

/// Compares the mesh's sharp edges with the true ones. Runs on all cores.
/// \throws InvalidInput if an option is not positive or a sample set's arrays differ in size.
CreaseMetrics compare_creases(const CurveSamples& exact, const CurveSamples& mesh,
                              const CreaseMetricsOptions& options = {});

/// Every measure of a mesh of a CAD-like part, lengths in bounding-box diagonals.
struct CadMetrics {
    double diagonal = 0.0;            ///< mm, of the solid's bounding box
    double chamfer = 0.0;             ///< mean distance both ways (SurfaceMetrics::chamfer_l1)
    double hausdorff = 0.0;           ///< largest distance either way
    double normal_consistency = 0.0;  ///< as SurfaceMetrics
    CreaseMetrics creases;
};

struct CadMetricsOptions {
    double sharp_angle_deg = 30.0;  ///< θ_s: the mesh's sharp edges (the true ones: exact_creases)
    double tolerance = 1e-3;        ///< τ of the Edge F-score, in diagonals
    double far = 1e-2;              ///< stray sharp edges lie farther than this, in diagonals
    double spacing = 0.1;           ///< longest piece of a mesh edge, mm (the exact samples' pitch)
};

/// `surface`: compare_surfaces() of the mesh against the exact surface; `exact_creases`:
/// sample_exact_creases() of the solid; `diagonal`: of the solid's box, mm.
/// \throws InvalidInput if the diagonal or an option is not positive.
CadMetrics measure_cad_part(const Mesh& mesh, const SurfaceMetrics& surface,
                            const CurveSamples& exact_creases, double diagonal,
                            const CadMetricsOptions& options = {});

}  // namespace resharp::eval
