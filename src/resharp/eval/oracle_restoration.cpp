#include "resharp/eval/oracle_restoration.h"

#include <cmath>
#include <numbers>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/pipeline/restore.h"
#include "resharp/restoration/feature_normals.h"

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
    FeatureNormals normals(mesh.vertex_count());
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;
        for (Index v : mesh.triangles[f]) {
            normals.add(v);
            normals.normal_at(v) = oracle.normals[v];
        }
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
    BandRestoration restored =
        restore_bands({mesh, connectivity, normals}, r.bands, exact, RestoreOptions{});
    r.refused_by_flip_test = restored.points.refused_by_flip_test;
    r.refused_by_spike_test = restored.points.refused_by_spike_test;
    r.refused_by_split = restored.guard.refused_by_quality + restored.guard.refused_by_guard +
                         restored.undone_points;
    r.mesh = std::move(restored.output.mesh);
    return r;
}

ExactNormalRestoration restore_with_exact_normals(const Mesh& mesh, const Oracle& oracle,
                                                  const RestoreOptions& options) {
    check_oracle(oracle, mesh);
    Detection d = detect_bands(mesh, build_connectivity(mesh), options);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        const Index w = static_cast<Index>(v);
        if (d.feature_normals.normal(w).isZero(0.0)) continue;
        d.feature_normals.normal_at(w) = oracle.normals[v];
        d.feature_normals.fit_correction_at(w) = 0.0f;  // exact normals need no margin
        // Nor a fitted field: its shape is not the exact surface's, and the guard would take its
        // angle to the exact normal as a margin.
        d.feature_normals.drop_field(w);
    }
    BandRestoration restored = restore_bands(d.surface(mesh), d.bands, d.feature_normals, options);
    return {std::move(restored.output.mesh),
            {d.edges.is_edge, d.features.vertex_patch, d.features.face_patch, d.bands.face_role}};
}

}  // namespace resharp::eval
