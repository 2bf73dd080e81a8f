#include "resharp/pipeline/restore.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <string>

#include "resharp/core/errors.h"
#include "resharp/core/stage_timer.h"
#include "resharp/curvature/local_height.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/restoration/band_classification.h"
#include "resharp/restoration/feature_normals.h"
#include "resharp/restoration/sharp_points.h"
#include "resharp/restoration/split.h"
#include "resharp/segmentation/edge_segmentation.h"
#include "resharp/segmentation/feature_segmentation.h"

namespace resharp {

std::string_view stage_name(Stage stage) {
    switch (stage) {
        case Stage::MeshBuilding:
            return "mesh building";
        case Stage::Curvature:
            return "curvature";
        case Stage::EdgeSegmentation:
            return "edge segmentation";
        case Stage::FeatureSegmentation:
            return "feature segmentation";
        case Stage::Classification:
            return "classification";
        case Stage::FeatureNormals:
            return "feature normals";
        case Stage::SharpPoints:
            return "sharp points";
        case Stage::Split:
            return "split";
    }
    return "unknown";
}

namespace {

void validate_mesh(const Mesh& mesh) {
    if (mesh.triangles.empty()) throw InvalidInput("the mesh has no triangles");
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        if (!mesh.positions[v].allFinite()) {
            throw InvalidInput("vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
        }
    }
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        for (Index v : mesh.triangles[f]) {
            if (v >= mesh.vertex_count()) {
                throw InvalidInput("triangle " + std::to_string(f) + " uses vertex " +
                                   std::to_string(v) + " but there are only " +
                                   std::to_string(mesh.vertex_count()) + " vertices");
            }
        }
    }
}

/// Runs the stages in order and times each; the one place that sequences them.
class Pipeline {
public:
    Pipeline(const Mesh& mesh, const RestoreOptions& options, RestoreResult& result)
        : mesh_(mesh), options_(options), report_(result.report), result_(result) {}

    Mesh run() {
        Connectivity connectivity;
        SurfaceNormals normals_of_input;
        timed(Stage::MeshBuilding, [&] {
            connectivity = build_connectivity(mesh_);
            report_.input = diagnose(mesh_, connectivity);
            normals_of_input = surface_normals(mesh_, connectivity);
        });
        const std::vector<Vec3>& face_normals = normals_of_input.face;
        const std::vector<Vec3>& vertex_normals = normals_of_input.vertex;
        PrincipalCurvatures curvatures;
        timed(Stage::Curvature, [&] {
            curvatures = estimate_principal_curvatures(mesh_, connectivity, vertex_normals);
        });
        EdgeSegmentation edges;
        timed(Stage::EdgeSegmentation, [&] {
            edges = segment_edges(mesh_, connectivity, curvatures, face_normals, options_.edges);
        });
        record(edges);
        FeatureSegmentation features;
        timed(Stage::FeatureSegmentation, [&] {
            features = segment_features(mesh_, connectivity, face_normals, edges.is_edge,
                                        options_.features);
        });
        record(features);
        BandClassification bands;
        timed(Stage::Classification, [&] {
            bands = classify_bands(mesh_, connectivity, face_normals, edges.is_edge,
                                   features.face_patch, features.vertex_patch, options_.bands);
        });
        if (options_.keep_segmentation) keep(edges, features, bands);
        report_.crossing_edges = bands.crossing_edges;
        report_.edge_triangles = bands.edge_triangles;
        report_.corner_triangles = bands.corner_triangles;
        FeatureNormals normals;
        timed(Stage::FeatureNormals, [&] {
            normals = feature_normals(mesh_, connectivity, face_normals, features.face_patch,
                                      features.vertex_patch, bands, options_.normals);
            override_normals(normals);
        });
        SharpPoints points;
        timed(Stage::SharpPoints, [&] {
            points = place_sharp_points(mesh_, connectivity, face_normals, bands, normals.normal,
                                        options_.points);
        });
        report_.refused_by_flip_test = points.refused_by_flip_test;
        report_.refused_by_spike_test = points.refused_by_spike_test;
        report_.refused_missing_normal = points.missing_normal;
        Mesh output;
        timed(Stage::Split, [&] {
            SplitReport split;
            output = split_band_triangles(
                mesh_, connectivity, face_normals, normals, vertex_normals, points, split,
                result_.source_face, {options_.points.spike_angle_deg, options_.check_clearance});
            record(split, points);
        });
        return output;
    }

private:
    template <class Work>
    void timed(Stage stage, Work&& work) {
        const StageTimer timer;
        work();
        report_.stage_time[static_cast<std::size_t>(stage)] = timer.elapsed();
    }

    void override_normals(FeatureNormals& normals) const {
        const auto& given = options_.normal_override;
        if (given.empty()) return;
        for (std::size_t v = 0; v < normals.normal.size(); ++v) {
            if (!normals.normal[v].isZero(0.0)) normals.normal[v] = given[v];
            normals.fit_correction_deg[v] = 0.0f;  // exact normals need no margin
        }
    }

    void keep(const EdgeSegmentation& edges, const FeatureSegmentation& features,
              const BandClassification& bands) {
        result_.segmentation = {edges.is_edge, features.vertex_patch, features.face_patch,
                                bands.face_role};
    }

    void record(const EdgeSegmentation& s) {
        report_.edge_vertices = s.edge_vertex_count();
        report_.clustered_edge_vertices = s.clustered_edge_vertices;
        report_.isolated_edge_vertices_removed = s.isolated_removed;
        report_.bridge_vertices_added = s.bridge_vertices_added;
        report_.flat_edge_vertices_removed = s.flat_removed;
        report_.kmeans_iterations = s.kmeans_iterations;
    }

    void record(const FeatureSegmentation& s) {
        report_.feature_patches = s.patch_count;
        report_.grown_patches = s.grown_patches;
        report_.band_patches = s.band_patches;
        report_.tiny_patches_absorbed = s.tiny_absorbed;
        report_.patch_merges = s.merges;
    }

    void record(const SplitReport& split, const SharpPoints& points) {
        report_.refused_by_quality = split.refused_by_quality;
        report_.refused_by_guard = split.refused_by_guard;
        report_.split_triangles = split.split_faces;
        report_.corner_points_inserted = static_cast<std::size_t>(
            std::count_if(points.corner_point.begin(), points.corner_point.end(),
                          [](Index id) { return id != kNoIndex; }));
        report_.edge_points_inserted = split.new_vertices - report_.corner_points_inserted;
    }

    const Mesh& mesh_;
    const RestoreOptions& options_;
    RestoreReport& report_;
    RestoreResult& result_;
};

}  // namespace

RestoreResult restore(const Mesh& input, const RestoreOptions& options) {
    validate_mesh(input);
    if (options.threads < 0) throw InvalidInput("thread count must not be negative");
    if (!options.normal_override.empty() &&
        options.normal_override.size() != input.vertex_count()) {
        throw InvalidInput("normal override has " + std::to_string(options.normal_override.size()) +
                           " normals for " + std::to_string(input.vertex_count()) + " vertices");
    }
    RestoreResult result;
    RestoreReport& report = result.report;
    report.input_vertices = input.vertex_count();
    report.input_triangles = input.face_count();
    const StageTimer total;
    tbb::task_arena arena(options.threads == 0 ? tbb::task_arena::automatic : options.threads);
    arena.execute([&] { result.mesh = Pipeline(input, options, result).run(); });
    report.total_time = total.elapsed();
    report.output_vertices = result.mesh.vertex_count();
    report.output_triangles = result.mesh.face_count();
    return result;
}

}  // namespace resharp
