#include "resharp/eval/surface_samples.h"

#include <algorithm>
#include <cmath>

namespace resharp::eval {

SurfaceSamples sample_exact_surface(const sim::DexelGrid& grid) {
    SurfaceSamples s;
    s.spacing = grid.spec.pitch;
    for (int axis = 0; axis < 3; ++axis) {
        const auto& rays = grid.rays[axis];
        for (std::size_t r = 0; r < rays.size(); ++r) {
            if (rays[r].empty()) continue;
            const sim::Ray ray = grid.spec.ray(axis, r);
            for (const sim::Interval& interval : rays[r]) {
                for (const sim::Crossing* c : {&interval.enter, &interval.exit}) {
                    s.points.push_back(ray.point(c->t));
                    s.normals.push_back(c->normal);
                }
            }
        }
    }
    return s;
}

namespace {

/// The grid lines of family `axis` through the projection of one triangle: inclusive node
/// ranges along the two other axes.
struct LineRange {
    int lo[2], hi[2];
};

LineRange lines_over(const sim::GridSpec& spec, int axis, const Vec3& lo, const Vec3& hi) {
    LineRange r{};
    for (int k = 0; k < 2; ++k) {
        const int a = (axis + 1 + k) % 3;
        const double first = std::ceil((lo[a] - spec.origin[a]) / spec.pitch);
        const double last = std::floor((hi[a] - spec.origin[a]) / spec.pitch);
        r.lo[k] = static_cast<int>(std::max(first, 0.0));
        r.hi[k] = static_cast<int>(std::min(last, double(spec.counts[a] - 1)));
    }
    return r;
}

/// Twice the signed area of (p, q, r) in 2D.
double orient(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
}

void sample_face(const Vec3 (&v)[3], const sim::GridSpec& spec, SurfaceSamples& out) {
    const Vec3 n = (v[1] - v[0]).cross(v[2] - v[0]);
    if (n.squaredNorm() == 0.0) return;
    const Vec3 unit = n.normalized();
    const Vec3 lo = v[0].cwiseMin(v[1]).cwiseMin(v[2]), hi = v[0].cwiseMax(v[1]).cwiseMax(v[2]);
    for (int axis = 0; axis < 3; ++axis) {
        if (n[axis] == 0.0) continue;
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        const Eigen::Vector2d p[3] = {{v[0][b], v[0][c]}, {v[1][b], v[1][c]}, {v[2][b], v[2][c]}};
        const LineRange range = lines_over(spec, axis, lo, hi);
        for (int j = range.lo[1]; j <= range.hi[1]; ++j) {
            for (int i = range.lo[0]; i <= range.hi[0]; ++i) {
                const Eigen::Vector2d q(spec.node(b, i), spec.node(c, j));
                const double w0 = orient(p[1], p[2], q), w1 = orient(p[2], p[0], q),
                             w2 = orient(p[0], p[1], q);
                const bool inside =
                    (w0 >= 0 && w1 >= 0 && w2 >= 0) || (w0 <= 0 && w1 <= 0 && w2 <= 0);
                if (!inside) continue;
                Vec3 x;
                x[b] = q.x();
                x[c] = q.y();
                x[axis] =
                    v[0][axis] - (n[b] * (q.x() - v[0][b]) + n[c] * (q.y() - v[0][c])) / n[axis];
                out.points.push_back(x);
                out.normals.push_back(unit);
            }
        }
    }
}

}  // namespace

SurfaceSamples sample_mesh(const Mesh& mesh, const sim::GridSpec& spec) {
    SurfaceSamples s;
    for (const Triangle& t : mesh.triangles) {
        const Vec3 v[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
        sample_face(v, spec, s);
    }
    return s;
}

}  // namespace resharp::eval
