#pragma once
/// Ground truth from the simulator's oracle (docs/design.md §5): where the sharp edges and corners
/// are, and how many of them a restored mesh put back.

#include <cstdint>
#include <span>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp::eval {

/// The exact data the simulator writes beside its mesh, one entry per vertex.
struct Oracle {
    std::vector<Vec3> normals;           ///< #V exact unit surface normals
    std::vector<std::int32_t> surfaces;  ///< #V id of the surface each vertex lies on
};

/// Where an ideal sharp point comes from.
enum class IdealKind : std::uint8_t {
    Edge,    ///< a crossing edge: eq. 5.2 with the exact normals of its two vertices
    Corner,  ///< a corner triangle: eq. 5.3 with the exact normals of its three vertices
};

struct IdealPoint {
    Vec3 position = Vec3::Zero();
    IdealKind kind = IdealKind::Edge;
    Index face = kNoIndex;  ///< a face holding the crossing edge, or the corner triangle
    Index vertices[3] = {kNoIndex, kNoIndex, kNoIndex};  ///< edge: two, corner: three
    bool on_boundary = false;  ///< a crossing edge with one face: left alone by restoration
    /// A crossing edge whose exact tangent planes meet beyond its chord: eq. 5.4 fails even with
    /// the exact normals, and the point lies over neither face of the edge. Splitting the edge
    /// there folds its faces, so no restoration that splits crossing edges (the paper's §5.2)
    /// can put it back; the crossing runs nearly along the sharp edge rather than across it.
    bool beyond_chord = false;
};

struct IdealPointOptions {
    /// theta_s: two vertices meet at a sharp junction when they lie on different surfaces and
    /// their exact normals differ by more than this (degrees).
    double sharp_angle_deg = 30.0;
};

/// \throws InvalidInput unless the oracle has one normal and one surface per vertex of `mesh`.
void check_oracle(const Oracle& oracle, const Mesh& mesh);

/// True when vertices u and v meet at a sharp junction: they lie on different surfaces and
/// the cosine between their exact normals is below `min_cosine` (the cosine of theta_s).
inline bool is_sharp_junction(const Oracle& oracle, Index u, Index v, double min_cosine) {
    return oracle.surfaces[u] != oracle.surfaces[v] &&
           oracle.normals[u].dot(oracle.normals[v]) < min_cosine;
}

/// Every crossing edge (a mesh edge at a sharp junction) and every corner triangle (three
/// vertices on three surfaces, pairwise at sharp junctions) of `mesh`, with its ideal point and
/// whether that point lies beyond the edge's chord.
/// Edges come in order of their lowest half-edge, then corners in face order. Junctions whose
/// equations have no single solution (parallel normals) are left out.
std::vector<IdealPoint> find_ideal_points(const Mesh& mesh, const Oracle& oracle,
                                          const IdealPointOptions& options = {});

/// IdealPoint::beyond_chord for `point` (an Edge ideal point of `mesh`, `c` its connectivity)
/// placed at p instead: eq. 5.4 fails with the exact normals and p lies over neither face.
/// \throws InvalidInput if point.vertices[0] is not a vertex of point.face.
bool is_beyond_chord(const Mesh& mesh, const Connectivity& c, const Oracle& oracle,
                     const IdealPoint& point, const Vec3& p);

/// For each ideal point, the distance to the nearest of `candidates` (infinity if none within
/// `search_radius`), found through a uniform grid with cells of search_radius.
std::vector<double> nearest_distances(std::span<const IdealPoint> ideal,
                                      std::span<const Vec3> candidates, double search_radius);

}  // namespace resharp::eval
