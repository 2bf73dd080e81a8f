#pragma once
/// The split (paper §5.2, after Attene et al.'s EdgeSharpener): every accepted edge point is
/// inserted on its crossing edge and every corner point inside its corner triangle, and the
/// faces are re-triangulated so that consecutive new points are joined by mesh edges. The
/// restored sharp edge is then a chain of mesh edges, a crease that viewers show as one line.

#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp {

struct SplitOptions {
    /// §5.3: pieces joining vertices whose normals differ by more than this (degrees) stand
    /// across thin material and must clear each normal by twice the usual margin.
    double spike_angle_deg = SharpPointOptions{}.spike_angle_deg;
    /// The guard's clearance check (clearance.h): every new piece is tested against the
    /// triangles near it and a point whose pieces would meet one is dropped. Off by default:
    /// on the four benchmark parts it refused nothing (the orientation checks already keep
    /// every piece clear; docs/results.md counts self-intersections with CGAL), and it costs a
    /// third of restore() on one thread (mech: 30 of 100 ms). Turn it on where a guarantee is
    /// worth that.
    bool check_clearance = false;
};

struct SplitReport {
    std::size_t refused_by_quality = 0;  ///< points dropped because a piece would flip or collapse
    /// points dropped by the guard: a piece would turn against the face it replaces, stand
    /// almost on edge across thin material, or meet another triangle
    std::size_t refused_by_guard = 0;
    std::size_t split_faces = 0;  ///< input faces replaced by pieces
    std::size_t new_vertices = 0;
    std::size_t output_faces = 0;
};

/// Takes the mesh, its connectivity, unit face normals (#F), feature normals with their fit
/// corrections (#V), plain vertex normals (#V, used where a vertex has no feature normal), the
/// points of place_sharp_points and the options. First drops, repeatedly, points of faces whose
/// pieces would collapse, turn against the surface they lie on or the face they replace, or,
/// with SplitOptions::check_clearance, meet another triangle of the output (the guard), so that
/// no output triangle is flipped (and, with the check, no self-intersection is made); dropped
/// points are removed from `points` (set to kNoIndex). Then builds the output: the input vertices
/// first, unchanged and in order, then the surviving points in `points` order; each face in input
/// order, either unchanged or replaced by its pieces. `source_face` receives, per output face, the
/// input face it came from.
Mesh split_band_triangles(const Mesh& mesh, const Connectivity& connectivity,
                          const std::vector<Vec3>& face_normals,
                          const FeatureNormals& feature_normals,
                          const std::vector<Vec3>& vertex_normals, SharpPoints& points,
                          SplitReport& report, std::vector<Index>& source_face,
                          const SplitOptions& options = {});

}  // namespace resharp
