#include "resharp/eval/exact_creases.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace resharp::eval {
namespace {

/// A boundary point found on a grid line of a plane.
struct Hit {
    std::size_t cell;
    Vec3 point;
    std::int32_t surface;
};

/// A point of a crease curve on one plane.
struct CreasePoint {
    Vec3 point, tangent;
};

class PlaneScan {
public:
    PlaneScan(const sim::CsgSolid& solid, const sim::DexelGrid& grid,
              const ExactCreaseOptions& options)
        : solid_(solid),
          grid_(grid),
          options_(options),
          min_cos_(std::cos(options.sharp_angle_deg * std::numbers::pi / 180.0)) {}

    /// The crease points on plane `index` across axis `a`, in a fixed order.
    std::vector<CreasePoint> scan(int a, int index) const {
        std::vector<Hit> hits = plane_hits(a, index);
        std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) {
            return x.cell != y.cell ? x.cell < y.cell : x.surface < y.surface;
        });
        const double plane = grid_.spec.node(a, index);
        std::vector<CreasePoint> found;
        for (std::size_t begin = 0; begin < hits.size();) {
            std::size_t end = begin;
            while (end < hits.size() && hits[end].cell == hits[begin].cell) ++end;
            // One start per pair of surfaces in the cell, from the first hit on each (hits are
            // sorted by surface).
            const auto first_on_its_surface = [&](std::size_t k) {
                return k == begin || hits[k - 1].surface != hits[k].surface;
            };
            for (std::size_t u = begin; u < end; ++u) {
                if (!first_on_its_surface(u)) continue;
                for (std::size_t v = u + 1; v < end; ++v) {
                    if (hits[v].surface == hits[u].surface || !first_on_its_surface(v)) continue;
                    add_unique(solve(hits[u], hits[v], a, plane), found);
                }
            }
            begin = end;
        }
        return found;
    }

private:
    /// The boundary crossings of the two ray families lying in the plane, each filed under the
    /// one or two plane cells whose side holds it.
    std::vector<Hit> plane_hits(int a, int index) const {
        const sim::GridSpec& spec = grid_.spec;
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const int cells_b = spec.counts[b] - 1, cells_c = spec.counts[c] - 1;
        std::vector<Hit> hits;
        const auto cell_along = [&](int axis, double t, int cells) {
            const int k = static_cast<int>(std::floor((t - spec.node(axis, 0)) / spec.pitch));
            return std::clamp(k, 0, cells - 1);
        };
        const auto file = [&](int jb, int jc, const Vec3& p, std::int32_t surface) {
            if (jb >= 0 && jb < cells_b && jc >= 0 && jc < cells_c) {
                hits.push_back(
                    {static_cast<std::size_t>(jb) + std::size_t(cells_b) * jc, p, surface});
            }
        };
        // Family b in this plane: the rays at (i_c = k, i_a = index), index k + n_c * index.
        for (int k = 0; k < spec.counts[c]; ++k) {
            const std::size_t ray = std::size_t(k) + std::size_t(spec.counts[c]) * index;
            for_each_crossing(b, ray, [&](const Vec3& p, double t, std::int32_t s) {
                const int j = cell_along(b, t, cells_b);
                file(j, k, p, s);
                file(j, k - 1, p, s);
            });
        }
        // Family c in this plane: the rays at (i_a = index, i_b = j), index index + n_a * j.
        for (int j = 0; j < spec.counts[b]; ++j) {
            const std::size_t ray = std::size_t(index) + std::size_t(spec.counts[a]) * j;
            for_each_crossing(c, ray, [&](const Vec3& p, double t, std::int32_t s) {
                const int k = cell_along(c, t, cells_c);
                file(j, k, p, s);
                file(j - 1, k, p, s);
            });
        }
        return hits;
    }

    template <class Visit>
    void for_each_crossing(int axis, std::size_t ray_index, Visit&& visit) const {
        const auto& intervals = grid_.rays[axis][ray_index];
        if (intervals.empty()) return;
        const sim::Ray ray = grid_.spec.ray(axis, ray_index);
        for (const sim::Interval& i : intervals) {
            for (const sim::Crossing* x : {&i.enter, &i.exit}) {
                visit(ray.point(x->t), x->t, x->surface);
            }
        }
    }

    /// The crease point between the surfaces of two hits on the plane x_a = plane, if any.
    std::optional<CreasePoint> solve(const Hit& h1, const Hit& h2, int a, double plane) const {
        const sim::CsgSurface& f1 = solid_.surfaces()[h1.surface];
        const sim::CsgSurface& f2 = solid_.surfaces()[h2.surface];
        const double pitch = grid_.spec.pitch;
        const Vec3 start = 0.5 * (h1.point + h2.point);
        Vec3 p = start;
        p[a] = plane;
        bool converged = false;
        for (int step = 0; step < options_.newton_steps; ++step) {
            const Eigen::Vector3d residual(f1.value(p), f2.value(p), 0.0);
            if (residual.cwiseAbs().maxCoeff() <= 1e-10 * pitch) {
                converged = true;
                break;
            }
            Eigen::Matrix3d jacobian;
            jacobian.row(0) = f1.gradient(p).transpose();
            jacobian.row(1) = f2.gradient(p).transpose();
            jacobian.row(2) = Vec3::Unit(a).transpose();
            // The curve nearly in the plane, or a surface without a gradient here: no crossing.
            if (std::abs(jacobian.determinant()) < 1e-9) return std::nullopt;
            p -= jacobian.partialPivLu().solve(residual);
            if ((p - start).norm() > 2.0 * std::sqrt(2.0) * pitch) return std::nullopt;
        }
        if (!converged) return std::nullopt;
        const Vec3 n1 = f1.normal(p), n2 = f2.normal(p);
        if (!(n1.dot(n2) < min_cos_) || !is_wedge(p, n1, n2, pitch)) return std::nullopt;
        const Vec3 tangent = n1.cross(n2).normalized();
        return CreasePoint{p, tangent};
    }

    /// Whether the solid near p is the wedge between two surfaces with outward normals n1, n2:
    /// of the four sectors they make, only the one behind both is inside, or only the one in
    /// front of both outside.
    bool is_wedge(const Vec3& p, const Vec3& n1, const Vec3& n2, double pitch) const {
        const double c = n1.dot(n2);
        const Vec3 u1 = (n1 - c * n2).normalized();  // n1 . u1 > 0, n2 . u1 = 0
        const Vec3 u2 = (n2 - c * n1).normalized();
        const double step = 1e-3 * pitch;
        int inside = 0;
        bool behind = false, front = false;
        for (const double s1 : {-1.0, 1.0}) {
            for (const double s2 : {-1.0, 1.0}) {
                const bool in = solid_.contains(p + step * (s1 * u1 + s2 * u2).normalized());
                inside += in;
                if (s1 < 0 && s2 < 0) behind = in;
                if (s1 > 0 && s2 > 0) front = in;
            }
        }
        return (inside == 1 && behind) || (inside == 3 && !front);
    }

    /// Adds `point` unless a crease point within 1e-6 pitch is there already: the same point
    /// found from another cell, or from another pair of coincident surfaces (the faces of two
    /// united boxes in one plane, either of which the rays may report).
    void add_unique(const std::optional<CreasePoint>& point,
                    std::vector<CreasePoint>& found) const {
        if (!point) return;
        const double same = 1e-6 * grid_.spec.pitch;
        for (const CreasePoint& q : found) {
            if ((q.point - point->point).norm() < same) return;
        }
        found.push_back(*point);
    }

    const sim::CsgSolid& solid_;
    const sim::DexelGrid& grid_;
    const ExactCreaseOptions& options_;
    double min_cos_;
};

}  // namespace

CurveSamples sample_exact_creases(const sim::CsgSolid& solid, const sim::DexelGrid& grid,
                                  const ExactCreaseOptions& options) {
    const PlaneScan scan(solid, grid, options);
    std::vector<std::pair<int, int>> planes;
    for (int a = 0; a < 3; ++a) {
        for (int i = 0; i < grid.spec.counts[a]; ++i) planes.emplace_back(a, i);
    }
    std::vector<std::vector<CreasePoint>> found(planes.size());
    tbb::parallel_for(std::size_t{0}, planes.size(), [&](std::size_t k) {
        found[k] = scan.scan(planes[k].first, planes[k].second);
    });
    CurveSamples out;
    const double pitch = grid.spec.pitch;
    for (const auto& plane : found) {
        for (const CreasePoint& c : plane) {
            out.points.push_back(c.point);
            out.tangents.push_back(c.tangent);
            out.weights.push_back(pitch / c.tangent.lpNorm<1>());
            out.half_spans.push_back(0.5 * std::sqrt(3.0) * pitch);
        }
    }
    return out;
}

}  // namespace resharp::eval
