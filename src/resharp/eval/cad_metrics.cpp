#include "resharp/eval/cad_metrics.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "resharp/core/errors.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/mesh/uniform_grid.h"

namespace resharp::eval {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + s * ab - p).norm();
}

}  // namespace

std::vector<double> crease_distances(const CurveSamples& from, const CurveSamples& to) {
    if (to.size() == 0)
        return std::vector<double>(from.size(), std::numeric_limits<double>::infinity());
    const auto end = [&](std::size_t k, double side) {
        return Vec3(to.points[k] + side * to.half_spans[k] * to.tangents[k]);
    };
    const double mean_span =
        std::accumulate(to.half_spans.begin(), to.half_spans.end(), 0.0) / double(to.size());
    const detail::UniformGrid grid(
        to.size(),
        [&](std::size_t k) { return detail::Box3(end(k, -1.0), end(k, -1.0)).extend(end(k, 1.0)); },
        std::max(4.0 * mean_span, 1e-12));
    std::vector<double> d(from.size());
    tbb::parallel_for(std::size_t{0}, from.size(), [&](std::size_t i) {
        const Vec3& p = from.points[i];
        d[i] =
            grid.nearest(p,
                         [&](Index k) { return distance_to_segment(p, end(k, -1.0), end(k, 1.0)); })
                .second;
    });
    return d;
}

namespace {

/// Weighted mean of f(d) over the samples.
template <class F>
double weighted_mean(const CurveSamples& s, const std::vector<double>& d, F&& f) {
    double sum = 0.0, weight = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        sum += s.weights[i] * f(d[i]);
        weight += s.weights[i];
    }
    return weight > 0.0 ? sum / weight : 0.0;
}

void check(const CurveSamples& s, const char* what) {
    if (s.tangents.size() != s.size() || s.weights.size() != s.size() ||
        s.half_spans.size() != s.size()) {
        throw InvalidInput(std::string(what) + ": sample arrays differ in size");
    }
}

}  // namespace

double CurveSamples::total_length() const {
    return std::accumulate(weights.begin(), weights.end(), 0.0);
}

CurveSamples sample_mesh_creases(const Mesh& mesh, double sharp_angle_deg, double spacing) {
    if (!(spacing > 0.0)) throw InvalidInput("crease sample spacing must be positive");
    const Connectivity connectivity = build_connectivity(mesh);
    const std::vector<Vec3> normals = face_normals(mesh);
    const double min_cos = std::cos(sharp_angle_deg * std::numbers::pi / 180.0);
    CurveSamples s;
    for (Index h = 0; h < connectivity.twin.size(); ++h) {
        const Index twin = connectivity.twin[h];
        if (connectivity.edge_kind[h] != EdgeKind::Manifold || twin < h) continue;
        const Vec3 &n1 = normals[face_of(h)], &n2 = normals[face_of(twin)];
        if (n1.isZero() || n2.isZero() || !(n1.dot(n2) < min_cos)) continue;
        const Vec3& a = mesh.positions[tail_vertex(mesh, h)];
        const Vec3& b = mesh.positions[head_vertex(mesh, h)];
        const double length = (b - a).norm();
        if (length == 0.0) continue;
        // Pieces no longer than `spacing`: at most length / spacing + 1 of them.
        const int pieces = std::max(1, static_cast<int>(std::ceil(length / spacing)));
        const Vec3 tangent = (b - a) / length;
        for (int k = 0; k < pieces; ++k) {
            s.points.push_back(a + (k + 0.5) / pieces * (b - a));
            s.tangents.push_back(tangent);
            s.weights.push_back(length / pieces);
            s.half_spans.push_back(0.5 * length / pieces);
            s.half_edges.push_back(h);
        }
    }
    return s;
}

CreaseMetrics compare_creases(const CurveSamples& exact, const CurveSamples& mesh,
                              const CreaseMetricsOptions& o) {
    check(exact, "the true sharp edges");
    check(mesh, "the mesh's sharp edges");
    if (!(o.tolerance > 0.0) || !(o.far > 0.0) || !(o.unit > 0.0)) {
        throw InvalidInput("crease metrics: tolerance, far and unit must be positive");
    }
    CreaseMetrics m;
    m.true_samples = exact.size();
    m.mesh_samples = mesh.size();
    m.true_length = exact.total_length() / o.unit;
    m.mesh_length = mesh.total_length() / o.unit;
    m.length_ratio = m.true_length > 0.0 ? m.mesh_length / m.true_length : kNaN;
    if (exact.size() == 0 || mesh.size() == 0) {
        // Nothing on one side: no distance to measure; F-score 1 only when both are empty.
        const bool both = exact.size() == 0 && mesh.size() == 0;
        m.ecd = both ? 0.0 : kNaN;
        m.precision = mesh.size() == 0 ? 1.0 : 0.0;
        m.recall = exact.size() == 0 ? 1.0 : 0.0;
        m.ef1 = both ? 1.0 : 0.0;
        m.stray_length = m.mesh_length;
        return m;
    }
    std::vector<double> from_exact = crease_distances(exact, mesh);
    std::vector<double> from_mesh = crease_distances(mesh, exact);
    for (double& d : from_exact) d /= o.unit;
    for (double& d : from_mesh) d /= o.unit;
    const auto square = [](double d) { return d * d; };
    const auto within = [&](double d) { return d <= o.tolerance ? 1.0 : 0.0; };
    m.ecd = weighted_mean(exact, from_exact, square) + weighted_mean(mesh, from_mesh, square);
    m.recall = weighted_mean(exact, from_exact, within);
    m.precision = weighted_mean(mesh, from_mesh, within);
    m.stray_length = m.mesh_length * weighted_mean(mesh, from_mesh,
                                                   [&](double d) { return d > o.far ? 1.0 : 0.0; });
    m.ef1 = m.precision + m.recall > 0.0 ? 2.0 * m.precision * m.recall / (m.precision + m.recall)
                                         : 0.0;
    return m;
}

CadMetrics measure_cad_part(const Mesh& mesh, const SurfaceMetrics& surface,
                            const CurveSamples& exact_creases, double diagonal,
                            const CadMetricsOptions& options) {
    if (!(diagonal > 0.0)) throw InvalidInput("the part's diagonal must be positive");
    CadMetrics m;
    m.diagonal = diagonal;
    m.chamfer = surface.chamfer_l1 / diagonal;
    m.hausdorff = surface.hausdorff / diagonal;
    m.normal_consistency = surface.normal_consistency;
    m.creases = compare_creases(
        exact_creases, sample_mesh_creases(mesh, options.sharp_angle_deg, options.spacing),
        {.tolerance = options.tolerance, .far = options.far, .unit = diagonal});
    return m;
}

}  // namespace resharp::eval
