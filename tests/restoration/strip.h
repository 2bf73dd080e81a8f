#pragma once
// A strip of two chamfer triangles across a convex right-angle edge along z, the smallest band
// the guard, the split and the harm check can be tested on: a0, a1 on the top face y = 0, b0, b1
// on the side face x = 0; the crossing edge a1-b0 has its ideal point at (0, 0, 0.75). And a
// corner triangle with the three faces across its edges, for the corner's points.

#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/input_surface.h"
#include "resharp/restoration/sharp_points.h"

namespace resharp::test {

struct Strip {
    Mesh mesh;
    Connectivity connectivity;
    SurfaceNormals normals;
    FeatureNormals feature_normals;  ///< exact: the top's and the side's normals

    std::vector<Vec3> given_normals;  ///< per vertex: its feature normal (zero: none)

    InputSurface surface() const { return {mesh, connectivity, normals}; }
    /// Rebuilds adjacency and normals after the mesh changed; new vertices have no feature
    /// normal.
    void rebuild() {
        connectivity = build_connectivity(mesh);
        normals = surface_normals(mesh, connectivity);
        given_normals.resize(mesh.vertex_count(), Vec3::Zero());
        set_feature_normals(given_normals);
    }
    /// Feature normals `given` (per vertex; zero: none), without corrections or fields.
    void set_feature_normals(std::vector<Vec3> given) {
        given_normals = std::move(given);
        feature_normals = FeatureNormals(given_normals.size());
        for (Index v = 0; v < given_normals.size(); ++v) {
            if (given_normals[v].isZero(0.0)) continue;
            feature_normals.add(v);
            feature_normals.normal_at(v) = given_normals[v];
        }
    }
};

inline Strip make_strip() {
    Strip s;
    s.mesh.positions = {{-0.3, 0, 0}, {-0.25, 0, 1}, {0, -0.2, 0.5}, {0, -0.3, 1.5}};
    s.mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    s.given_normals = {{0, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 0, 0}};
    s.rebuild();
    return s;
}

/// The strip with a1 moved past the sharp edge, onto the top plane's continuation (a vertex
/// beyond a cusp): eq. 5.4 fails for a1-b0, and the ideal point (0, 0, 0.75) lies over face 0.
inline Strip make_strip_past_the_edge() {
    Strip s = make_strip();
    s.mesh.positions[1] = Vec3(0.05, 0, 1);
    s.rebuild();
    return s;
}

/// The point of the crossing edge a1-b0, placed with the exact normals (eq. 5.2 on these
/// planes).
inline SharpPoints points_on_edge_a1_b0(const Strip& s, const SharpPointOptions& options = {}) {
    BandClassification bands;
    bands.is_crossing.assign(3 * s.mesh.face_count(), 0);
    bands.face_role.assign(s.mesh.face_count(), BandRole::Edge);  // every face of a strip
    for (Index h = 0; h < bands.is_crossing.size(); ++h) {
        const Index u = tail_vertex(s.mesh, h), v = head_vertex(s.mesh, h);
        if ((u == 1 && v == 2) || (u == 2 && v == 1)) bands.is_crossing[h] = 1;
    }
    return place_sharp_points(s.mesh, s.connectivity, s.normals.face, bands, s.feature_normals,
                              options);
}

/// A corner triangle (face 0: vertices 0, 1, 2) and the faces across its edges 0, 1, 2 (faces
/// 1, 2, 3, whose third vertices are 3, 4, 5), with exact feature normals, as cut from mech.stl
/// (one grid pitch a unit): every edge whose ends' normals differ crosses. Its points are placed
/// by eq. 5.2-5.3, and on the crossing edges of the mesh's border, which eq. 5.2 leaves alone,
/// by `border_points` (half-edge and point, as on mech.stl): the sharp edges go on there.
struct CornerWithNeighbours {
    Strip s;
    SharpPoints points;

    CornerWithNeighbours(const std::array<Vec3, 6>& positions, const std::array<Vec3, 6>& normals,
                         const std::vector<std::pair<Index, Vec3>>& border_points) {
        s.mesh.positions.assign(positions.begin(), positions.end());
        s.mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {2, 1, 4}, {0, 2, 5}};
        s.rebuild();
        s.set_feature_normals({normals.begin(), normals.end()});
        BandClassification bands;
        bands.face_role = {BandRole::Corner, BandRole::Edge, BandRole::Edge, BandRole::Edge};
        for (Index h = 0; h < 3 * s.mesh.face_count(); ++h) {
            const Index u = tail_vertex(s.mesh, h), v = head_vertex(s.mesh, h);
            bands.is_crossing.push_back(normals[u] != normals[v]);
        }
        points =
            place_sharp_points(s.mesh, s.connectivity, s.normals.face, bands, s.feature_normals);
        for (const auto& [h, x] : border_points) {
            EXPECT_TRUE(bands.is_crossing[h] && s.connectivity.twin[h] == kNoIndex);
            points.slots.set_edge_point(h, static_cast<Index>(points.points.size()));
            points.points.push_back(x);
        }
    }
    Index corner() const { return points.slots.corner_point(0); }
    Index edge(Index k) const { return points.slots.edge_point(k); }  ///< face 0's edge k
    Index twin(Index k) const { return s.connectivity.twin[k]; }
};

}  // namespace resharp::test
