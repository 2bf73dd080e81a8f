#pragma once
/// The ceiling of the restoration itself: the split (paper §5.2-5.3) run on the oracle's crossing
/// edges and corner triangles with the exact normals, so that neither segmentation nor normal
/// estimation can lose a point. What it still misses are ideal points beyond their chord (eq. 5.4
/// fails even with exact normals: no edge split reaches them) and points the split's own
/// checks drop.

#include <vector>

#include "resharp/eval/ideal_points.h"
#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/restore.h"
#include "resharp/restoration/band_classification.h"

namespace resharp::eval {

/// The oracle's classification: every manifold edge between two non-degenerate faces whose
/// vertices meet at a sharp junction (IdealPointOptions::sharp_angle_deg) crosses; face roles as
/// classify_faces() gives them.
/// \throws InvalidInput if the oracle does not have one entry per vertex.
BandClassification oracle_bands(const Mesh& mesh, const Oracle& oracle,
                                const IdealPointOptions& options = {});

struct OracleRestoration {
    Mesh mesh;  ///< as restore() gives it: the input's vertices first, then new points
    BandClassification bands;               ///< oracle_bands()
    std::size_t refused_by_flip_test = 0;   ///< crossing edges failing eq. 5.4 with exact normals
    std::size_t refused_by_spike_test = 0;  ///< corner triangles failing the spike test
    /// points the guard refused or the harm check undid
    std::size_t refused_by_split = 0;
};

/// Places eq. 5.2 / 5.3 points on oracle_bands() with the oracle's normals at every vertex of
/// an edge or corner triangle, and restores them as restore() does with its default options
/// (guard, split and harm check: restore_bands()).
/// \throws InvalidInput if the oracle does not have one entry per vertex.
OracleRestoration restore_from_oracle(const Mesh& mesh, const Oracle& oracle,
                                      const IdealPointOptions& options = {});

/// The ceiling of the placement step on resharp's own detection: restore()'s stages with the
/// oracle's exact normals in place of the feature normals (eq. 5.1) at every vertex that has
/// one. Gives the restored mesh and the segmentation (as keep_segmentation does); no duplicate
/// faces are removed (a simulated mesh has none).
/// \throws InvalidInput if the oracle does not have one entry per vertex, or as restore().
struct ExactNormalRestoration {
    Mesh mesh;
    Segmentation segmentation;
};
ExactNormalRestoration restore_with_exact_normals(const Mesh& mesh, const Oracle& oracle,
                                                  const RestoreOptions& options = {});

}  // namespace resharp::eval
