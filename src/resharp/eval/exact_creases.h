#pragma once
/// The true sharp edges of a CSG solid as dense samples: points on the curves where two of its
/// surfaces meet on its boundary with outward normals more than θ_s apart (cad_metrics.h scores
/// a mesh's sharp edges against them).
///
/// How they are found. Every grid plane of a tri-dexel grid of the solid (one per node
/// coordinate, on all three axes) cuts each crease curve in points. Within one plane, the grid
/// lines of the two other families cross the solid's cross-section on its boundary; two such
/// crossings on different surfaces within one cell of the plane bracket a corner of the
/// cross-section. From their midpoint a Newton iteration (at most `newton_steps` steps) solves
/// f1 = f2 = 0 on the plane (the two surfaces' implicit functions, sim::CsgSurface). The point is
/// kept when it converges within two cells of the start, its two outward normals part by more
/// than θ_s, and the solid around it is the wedge of those two surfaces: of four points just off
/// it, one in each sector the two surfaces make, either only the one behind both is inside (a
/// convex edge) or only the one in front of both is outside (a concave edge). Where a surface
/// merely passes through the other (a face inside the material, a tangent fillet) the test fails.
///
/// Each point stands for pitch / |t|_1 of curve, t its unit tangent: a curve crosses the planes
/// of family a |t_a| / pitch times per unit length, so over the three families these weights sum
/// to the curve's length, to within about a pitch per curve end. Its piece reaches sqrt(3) / 2
/// pitch either way along t, enough to bridge the widest gap between a curve's crossings.

#include "resharp/eval/cad_metrics.h"
#include "resharp/sim/csg.h"
#include "resharp/sim/tridexel.h"

namespace resharp::eval {

struct ExactCreaseOptions {
    double sharp_angle_deg = 30.0;  ///< θ_s: surfaces whose normals part by more meet sharply
    int newton_steps = 30;          ///< bound of the iteration onto both surfaces
};

/// Samples the sharp edges of `solid` on the planes of `grid` (a grid that sampled it:
/// sample_solid(spec, solid)). Deterministic, on all cores.
CurveSamples sample_exact_creases(const sim::CsgSolid& solid, const sim::DexelGrid& grid,
                                  const ExactCreaseOptions& options = {});

}  // namespace resharp::eval
