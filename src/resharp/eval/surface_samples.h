#pragma once
/// Dense point samples of a surface with normals, taken where the lines of a ray grid cross it:
/// of the exact machined surface from the simulator's own tri-dexel crossings, and of a mesh by
/// intersecting the same rays with its triangles. One sampler for both keeps their densities
/// equal, and a mesh equal to the surface gives the very same points.

#include <vector>

#include "resharp/mesh/mesh.h"
#include "resharp/sim/tridexel.h"

namespace resharp::eval {

/// #S points with unit normals (outward).
struct SurfaceSamples {
    std::vector<Vec3> points;
    std::vector<Vec3> normals;
    /// The pitch of the ray grid the samples lie on (0: not known): a surface point may lie
    /// about that far from the sample nearest it.
    double spacing = 0.0;
    std::size_t size() const { return points.size(); }
};

/// Every interval end of every ray of `grid`: points exactly on the simulated surface with
/// their exact normals (docs/oracle.md). Ray by ray, family x then y then z.
SurfaceSamples sample_exact_surface(const sim::DexelGrid& grid);

/// Where the grid lines of `spec` (all three families) cross the triangles of `mesh`, with the
/// crossed face's unit normal. A line through a shared edge or vertex may give one point per
/// face touching it; degenerate faces give none.
SurfaceSamples sample_mesh(const Mesh& mesh, const sim::GridSpec& spec);

}  // namespace resharp::eval
