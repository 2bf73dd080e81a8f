#pragma once
/// How many ideal sharp points a restored mesh put back (docs/design.md §5, the paper's §6 rate).

#include <cstddef>
#include <span>
#include <vector>

#include "resharp/eval/ideal_points.h"
#include "resharp/eval/surface_samples.h"
#include "resharp/mesh/mesh.h"

namespace resharp::eval {

struct RestorationOptions {
    double pitch = 0.5;       ///< h, mm
    double tolerance = 0.05;  ///< tau, in h: an ideal point is restored by a new vertex this near
    /// An input vertex within tau restores an ideal point too: on the exact junction an input
    /// vertex may already lie on the sharp edge (the eq. 5.2 point is never one).
    bool count_input_vertices = false;
};

struct RestorationScore {
    std::size_t ideal_edges = 0;     ///< ideal points of crossing edges (boundary ones left out)
    std::size_t ideal_corners = 0;   ///< ideal points of corner triangles
    std::size_t restored_edges = 0;  ///< of those, with a new vertex within tau (or an input
                                     ///< vertex, with count_input_vertices)
    std::size_t restored_corners = 0;
    /// With count_input_vertices: of the restored ones, how many have an input vertex within tau.
    std::size_t restored_by_input_vertices = 0;
    double rate = 1.0;          ///< (restored edges + corners) / (ideal edges + corners); 1 if none
    double rate_edges = 1.0;    ///< restored_edges / ideal_edges; 1 if none
    double rate_corners = 1.0;  ///< restored_corners / ideal_corners; 1 if none
    /// Ideal edge points beyond their chord (IdealPoint::beyond_chord), and how many of them a
    /// new vertex happens to lie near all the same.
    std::size_t beyond_chord = 0;
    std::size_t restored_beyond_chord = 0;
    /// The rate over the ideal points not beyond their chord, the only ones a restoration that
    /// splits crossing edges can reach; 1 if none.
    double rate_within_reach = 1.0;
    std::size_t new_vertices = 0;      ///< output vertices after the input's
    std::size_t false_insertions = 0;  ///< new vertices farther than tau from every ideal point
    /// mm: the largest distance of a new vertex from the nearest exact sample, an upper bound on
    /// its distance from the exact surface (exact to within the sample pitch); 0 if none.
    double max_new_vertex_distance = 0.0;
    /// Per ideal point (same order as given): distance to the nearest new vertex (or output
    /// vertex, with count_input_vertices), mm (infinity if none within 4 h). Boundary ideal
    /// points get NaN.
    std::vector<double> ideal_distance;
};

/// Scores `output` against the `ideal` points of `input` (find_ideal_points). New vertices are
/// the output's vertices after the input's; `exact` samples the exact surface
/// (sample_exact_surface) for the distance of new vertices from it.
/// \throws InvalidInput if the output does not start with the input's vertices (same positions,
/// same order), `exact` is empty, or an option is not positive.
RestorationScore score_restoration(const Mesh& input, const Mesh& output,
                                   std::span<const IdealPoint> ideal, const SurfaceSamples& exact,
                                   const RestorationOptions& options = {});

/// \throws InvalidInput (naming the first mismatch) unless output's first #V vertices are
/// input's, position for position.
void check_output_extends_input(const Mesh& input, const Mesh& output);

}  // namespace resharp::eval
