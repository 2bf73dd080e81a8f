#include "resharp/eval/oracle_restoration.h"

#include <cmath>
#include <numbers>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/sharp_points.h"
#include "resharp/restoration/split.h"

namespace resharp::eval {
namespace {

BandClassification bands_of(const Mesh& mesh, const Connectivity& connectivity,
                            const std::vector<Vec3>& face_normals, const Oracle& oracle,
                            const IdealPointOptions& options) {
    const double min_cosine = std::cos(options.sharp_angle_deg * std::numbers::pi / 180.0);
    std::vector<std::uint8_t> is_crossing(connectivity.twin.size(), 0);
    for (Index h = 0; h < is_crossing.size(); ++h) {
        const Index twin = connectivity.twin[h];
        // As classify_bands(): only manifold edges between non-degenerate faces can be split.
        if (twin == kNoIndex || face_normals[face_of(h)].isZero(0.0) ||
            face_normals[face_of(twin)].isZero(0.0)) {
            continue;
        }
        is_crossing[h] =
            is_sharp_junction(oracle, tail_vertex(mesh, h), head_vertex(mesh, h), min_cosine);
    }
    return classify_faces(std::move(is_crossing));
}

/// The exact normal at every vertex of an edge or corner triangle, zero elsewhere, as
/// feature_normals() leaves vertices off the bands; exact normals need no fit margin.
FeatureNormals exact_feature_normals(const Mesh& mesh, const BandClassification& bands,
                                     const Oracle& oracle) {
    FeatureNormals normals{std::vector<Vec3>(mesh.vertex_count(), Vec3::Zero()),
                           std::vector<float>(mesh.vertex_count(), 0.0f)};
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;
        for (Index v : mesh.triangles[f]) normals.normal[v] = oracle.normals[v];
    }
    return normals;
}

}  // namespace

BandClassification oracle_bands(const Mesh& mesh, const Oracle& oracle,
                                const IdealPointOptions& options) {
    check_oracle(oracle, mesh);
    const Connectivity connectivity = build_connectivity(mesh);
    return bands_of(mesh, connectivity, face_normals(mesh), oracle, options);
}

OracleRestoration restore_from_oracle(const Mesh& mesh, const Oracle& oracle,
                                      const IdealPointOptions& options) {
    check_oracle(oracle, mesh);
    const Connectivity connectivity = build_connectivity(mesh);
    const SurfaceNormals normals = surface_normals(mesh, connectivity);
    OracleRestoration r;
    r.bands = bands_of(mesh, connectivity, normals.face, oracle, options);
    const FeatureNormals exact = exact_feature_normals(mesh, r.bands, oracle);
    SharpPoints points =
        place_sharp_points(mesh, connectivity, normals.face, r.bands, exact.normal);
    r.refused_by_flip_test = points.refused_by_flip_test;
    r.refused_by_spike_test = points.refused_by_spike_test;
    SplitReport split;
    std::vector<Index> source_face;
    r.mesh = split_band_triangles(mesh, connectivity, normals.face, exact, normals.vertex, points,
                                  split, source_face);
    r.refused_by_split = split.refused_by_quality + split.refused_by_guard;
    return r;
}

}  // namespace resharp::eval
