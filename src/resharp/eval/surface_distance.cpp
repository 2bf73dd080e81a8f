#include "resharp/eval/surface_distance.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"
#include "resharp/mesh/uniform_grid.h"

namespace resharp::eval {
namespace {

using detail::Box3;
using detail::face_grid;
using detail::UniformGrid;

/// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    }
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

/// Per sample of one set: distance to the other surface and |n . n'| there.
struct OneWay {
    std::vector<double> distance;
    std::vector<double> abs_dot;
};

UniformGrid point_grid(const std::vector<Vec3>& points, double cell) {
    return UniformGrid(
        points.size(), [&](std::size_t i) { return Box3(points[i], points[i]); }, cell);
}

template <class Body>
void parallel_for_each(std::size_t n, Body&& body) {
    tbb::parallel_for(std::size_t{0}, n, std::forward<Body>(body));
}

OneWay samples_to_mesh(const SurfaceSamples& s, const Mesh& mesh, double cell) {
    const std::vector<Vec3> face_normal = face_normals(mesh);  // zero where degenerate
    const UniformGrid grid = face_grid(mesh, cell);
    OneWay out{std::vector<double>(s.size()), std::vector<double>(s.size())};
    parallel_for_each(s.size(), [&](std::size_t i) {
        const Vec3& p = s.points[i];
        const auto [f, d] = grid.nearest(p, [&](Index face) {
            const Triangle& t = mesh.triangles[face];
            return (closest_on_triangle(p, mesh.positions[t[0]], mesh.positions[t[1]],
                                        mesh.positions[t[2]]) -
                    p)
                .norm();
        });
        out.distance[i] = d;
        out.abs_dot[i] = std::abs(s.normals[i].dot(face_normal[f]));  // 0: degenerate face
    });
    return out;
}

OneWay samples_to_samples(const SurfaceSamples& from, const SurfaceSamples& to, double cell) {
    const UniformGrid grid = point_grid(to.points, cell);
    OneWay out{std::vector<double>(from.size()), std::vector<double>(from.size())};
    parallel_for_each(from.size(), [&](std::size_t i) {
        const Vec3& p = from.points[i];
        const auto [j, d] = grid.nearest(p, [&](Index k) { return (to.points[k] - p).norm(); });
        out.distance[i] = d;
        out.abs_dot[i] = std::abs(from.normals[i].dot(to.normals[j]));
    });
    return out;
}

double mean(const std::vector<double>& v, auto&& f) {
    double sum = 0.0;
    for (double x : v) sum += f(x);
    return v.empty() ? 0.0 : sum / double(v.size());
}

double share_below(const std::vector<double>& v, double threshold) {
    return mean(v, [&](double d) { return d < threshold ? 1.0 : 0.0; });
}

double f_score(double precision, double recall) {
    return precision + recall > 0.0 ? 2.0 * precision * recall / (precision + recall) : 0.0;
}

/// The samples of `s` with a neighbour within `radius` whose normal satisfies `is_apart`.
SurfaceSamples edge_samples(const SurfaceSamples& s, double radius, double cell, auto&& is_apart) {
    const UniformGrid grid = point_grid(s.points, cell);
    std::vector<std::uint8_t> flag(s.size(), 0);
    parallel_for_each(s.size(), [&](std::size_t i) {
        grid.for_each_near(s.points[i], radius, [&](Index j) {
            if (!flag[i] && is_apart(s.normals[i], s.normals[j]) &&
                (s.points[j] - s.points[i]).norm() <= radius) {
                flag[i] = 1;
            }
        });
    });
    SurfaceSamples out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!flag[i]) continue;
        out.points.push_back(s.points[i]);
        out.normals.push_back(s.normals[i]);
    }
    return out;
}

EdgeMetrics edge_metrics(const SurfaceSamples& exact, const SurfaceSamples& mesh,
                         const SurfaceMetricsOptions& o, auto&& is_apart) {
    const double h = o.pitch;
    const SurfaceSamples e = edge_samples(exact, o.edge_radius * h, o.cell * h, is_apart);
    const SurfaceSamples m = edge_samples(mesh, o.edge_radius * h, o.cell * h, is_apart);
    EdgeMetrics r{e.size(), m.size(), 0.0, 1.0};
    if (e.size() == 0) return r;  // NDC: nothing to find, nothing missed
    if (m.size() == 0) return {e.size(), 0, std::numeric_limits<double>::quiet_NaN(), 0.0};
    const OneWay recall_way = samples_to_samples(e, m, o.cell * h);
    const OneWay precision_way = samples_to_samples(m, e, o.cell * h);
    auto square = [](double d) { return d * d; };
    r.ecd = mean(recall_way.distance, square) + mean(precision_way.distance, square);
    const double t = o.edge_f1_threshold * h;
    r.ef1 = f_score(share_below(precision_way.distance, t), share_below(recall_way.distance, t));
    return r;
}

void check(const SurfaceSamples& s, const char* what) {
    if (s.size() == 0) throw InvalidInput(std::string(what) + " has no samples");
    if (s.normals.size() != s.points.size()) {
        throw InvalidInput(std::string(what) + ": normals do not match the points");
    }
}

double percentile(std::vector<double> v, double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * double(v.size()))) - 1;
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[k];
}

}  // namespace

SurfaceMetrics compare_surfaces(const Mesh& mesh, const SurfaceSamples& mesh_samples,
                                const SurfaceSamples& exact, const SurfaceMetricsOptions& o) {
    check(mesh_samples, "the mesh");
    check(exact, "the exact surface");
    if (!(o.pitch > 0 && o.edge_radius > 0 && o.cell > 0 && o.f1_threshold > 0 &&
          o.edge_f1_threshold > 0)) {
        throw InvalidInput("surface metrics: pitch, radii and thresholds must be positive");
    }
    const double h = o.pitch;
    const OneWay from_exact = samples_to_mesh(exact, mesh, o.cell * h);
    const OneWay from_mesh = samples_to_samples(mesh_samples, exact, o.cell * h);

    SurfaceMetrics m;
    m.exact_samples = exact.size();
    m.mesh_samples = mesh_samples.size();
    auto identity = [](double d) { return d; };
    auto square = [](double d) { return d * d; };
    m.chamfer_l1 = 0.5 * (mean(from_exact.distance, identity) + mean(from_mesh.distance, identity));
    m.chamfer_l2 = mean(from_exact.distance, square) + mean(from_mesh.distance, square);
    std::vector<double> all = from_exact.distance;
    all.insert(all.end(), from_mesh.distance.begin(), from_mesh.distance.end());
    m.hausdorff = *std::max_element(all.begin(), all.end());
    m.hausdorff_p99 = percentile(std::move(all), 0.99);
    m.normal_consistency =
        0.5 * (mean(from_exact.abs_dot, identity) + mean(from_mesh.abs_dot, identity));
    m.f1 = f_score(share_below(from_mesh.distance, o.f1_threshold * h),
                   share_below(from_exact.distance, o.f1_threshold * h));

    const double max_abs_dot = o.edge_max_abs_dot;
    m.edges_ndc = edge_metrics(exact, mesh_samples, o, [&](const Vec3& a, const Vec3& b) {
        return std::abs(a.dot(b)) < max_abs_dot;
    });
    const double min_cos = std::cos(o.edge_dihedral_deg * std::numbers::pi / 180.0);
    m.edges_dihedral = edge_metrics(
        exact, mesh_samples, o, [&](const Vec3& a, const Vec3& b) { return a.dot(b) < min_cos; });
    return m;
}

}  // namespace resharp::eval
