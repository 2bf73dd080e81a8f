#pragma once
/// Detection scores (docs/design.md §5): the method's edge and corner triangles against the
/// triangles the oracle says hold a crossing edge or are corner triangles.

#include <cstddef>
#include <span>
#include <vector>

#include "resharp/eval/ideal_points.h"
#include "resharp/mesh/mesh.h"
#include "resharp/restoration/band_classification.h"

namespace resharp::eval {

/// Per face (#F) of `mesh`, the ground truth: Corner for a corner triangle (three vertices on
/// three surfaces, pairwise at sharp junctions), Edge for any other face holding a crossing
/// edge, None otherwise.
/// \throws InvalidInput if the oracle does not have one entry per vertex.
std::vector<BandRole> true_band_roles(const Mesh& mesh, const Oracle& oracle,
                                      const IdealPointOptions& options = {});

/// Precision and recall of one detected set of faces against the true one.
struct DetectionScore {
    std::size_t detected = 0;  ///< faces the method marked
    std::size_t actual = 0;    ///< faces the oracle marks
    std::size_t matched = 0;   ///< faces both mark
    double precision = 1.0;    ///< matched / detected; 1 if nothing detected
    double recall = 1.0;       ///< matched / actual; 1 if nothing to find
};

struct DetectionScores {
    DetectionScore bands;    ///< edge or corner triangles (any role) against any true role
    DetectionScore corners;  ///< corner triangles against true corner triangles
};

/// Compares the method's per-face roles (Segmentation::face_role, or read back from
/// `resharp restore --segments`) with true_band_roles(). Both #F.
/// \throws InvalidInput if the sizes differ.
DetectionScores score_detection(std::span<const BandRole> detected,
                                std::span<const BandRole> truth);

}  // namespace resharp::eval
