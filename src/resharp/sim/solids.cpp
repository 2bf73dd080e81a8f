#include "resharp/sim/solids.h"

#include <cmath>
#include <limits>

#include "resharp/core/errors.h"

namespace resharp::sim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Box of the vertices of the polytope: every feasible intersection point of three face planes.
Box3 polytope_bounds(const std::vector<HalfSpace>& faces) {
    Box3 box;
    const std::size_t n = faces.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            for (std::size_t k = j + 1; k < n; ++k) {
                Eigen::Matrix3d m;
                m << faces[i].normal.transpose(), faces[j].normal.transpose(),
                    faces[k].normal.transpose();
                if (std::abs(m.determinant()) < 1e-12) continue;
                const Vec3 x =
                    m.partialPivLu().solve(Vec3(faces[i].offset, faces[j].offset, faces[k].offset));
                const double scale = 1.0 + x.cwiseAbs().maxCoeff();
                bool feasible = true;
                for (const HalfSpace& f : faces) {
                    if (f.normal.dot(x) > f.offset + 1e-9 * scale) feasible = false;
                }
                if (feasible) box.extend(x);
            }
        }
    }
    return box;
}

/// The stretch of a line inside a circle or ball of radius r whose centre lies `across` from it
/// (a vector perpendicular to the line) and at `center` along it. A touching line gets a tiny
/// chord when the touching point counts as inside (kTouchingChord).
bool chord(double center, const Vec3& across, double r, double& t0, double& t1) {
    const double half_squared = r * r - across.squaredNorm();
    double half = 0.0;
    if (half_squared == 0.0 && boundary_is_inside(Vec3(across / r))) {
        half = kTouchingChord * r;
    } else if (half_squared > 0.0) {
        half = std::sqrt(half_squared);
    } else {
        return false;
    }
    t0 = center - half;
    t1 = center + half;
    return true;
}

}  // namespace

ConvexPolytope::ConvexPolytope(std::vector<HalfSpace> faces) : faces_(std::move(faces)) {
    for (const HalfSpace& f : faces_) {
        if (std::abs(f.normal.norm() - 1.0) > 1e-12) {
            throw InvalidInput("polytope face normal is not unit length");
        }
    }
    bounds_ = polytope_bounds(faces_);
    if (bounds_.isEmpty()) throw InvalidInput("polytope is empty or unbounded");
    // An unbounded polytope still has vertices; check each axis direction is capped.
    for (int a = 0; a < 3; ++a) {
        for (double sign : {-1.0, 1.0}) {
            bool capped = false;
            for (const HalfSpace& f : faces_) capped |= sign * f.normal[a] > 1e-12;
            if (!capped) throw InvalidInput("polytope is unbounded");
        }
    }
}

void ConvexPolytope::intersect(const Ray& ray, std::vector<Interval>& out) const {
    Crossing enter{-kInfinity, Vec3::Zero(), -1};
    Crossing exit{kInfinity, Vec3::Zero(), -1};
    for (const HalfSpace& f : faces_) {
        const double along = f.normal[ray.axis];
        const double room = f.offset - f.normal.dot(ray.origin);  // origin[axis] is 0
        if (along == 0.0) {
            // The ray is parallel to the face: all in or all out, a ray on the plane decided by
            // the shared perturbation rule.
            if (room < 0.0 || (room == 0.0 && !boundary_is_inside(f.normal))) return;
            continue;
        }
        const double t = room / along;
        if (along < 0.0) {
            if (t > enter.t) enter = {t, f.normal, f.surface};
        } else if (t < exit.t) {
            exit = {t, f.normal, f.surface};
        }
    }
    if (enter.t < exit.t) out.push_back({enter, exit});
}

ConvexPolytope axis_box(const Box3& box, std::int32_t first_surface) {
    if (box.isEmpty()) throw InvalidInput("box is empty");
    std::vector<HalfSpace> faces;
    for (int a = 0; a < 3; ++a) {
        const Vec3 e = Vec3::Unit(a);
        faces.push_back({-e, -box.min()[a], first_surface + 2 * a});
        faces.push_back({e, box.max()[a], first_surface + 2 * a + 1});
    }
    return ConvexPolytope(std::move(faces));
}

ZCylinder::ZCylinder(const Params& params) : p_(params) {
    if (!(p_.radius > 0.0) || !(p_.z_max > p_.z_min)) {
        throw InvalidInput("cylinder radius and height must be positive");
    }
}

Box3 ZCylinder::bounds() const {
    return Box3(Vec3(p_.center.x() - p_.radius, p_.center.y() - p_.radius, p_.z_min),
                Vec3(p_.center.x() + p_.radius, p_.center.y() + p_.radius, p_.z_max));
}

void ZCylinder::intersect(const Ray& ray, std::vector<Interval>& out) const {
    const Vec3 down(0, 0, -1), up(0, 0, 1);
    if (ray.axis == 2) {
        const Eigen::Vector2d offset = ray.origin.head<2>() - p_.center;
        const double d2 = offset.squaredNorm();
        const double r2 = p_.radius * p_.radius;
        if (d2 > r2) return;
        if (d2 == r2) {  // the ray lies on the curved face
            const Vec3 n(offset.x() / p_.radius, offset.y() / p_.radius, 0.0);
            if (!boundary_is_inside(n)) return;
        }
        out.push_back({{p_.z_min, down, p_.bottom_surface}, {p_.z_max, up, p_.top_surface}});
        return;
    }
    const double z = ray.origin.z();
    if (z < p_.z_min || z > p_.z_max) return;
    if ((z == p_.z_min && !boundary_is_inside(down)) ||
        (z == p_.z_max && !boundary_is_inside(up))) {
        return;
    }
    const int across = 1 - ray.axis;  // x-rays vary in x and sit at fixed y, and vice versa
    const double d = ray.origin[across] - p_.center[across];
    double t0, t1;
    if (!chord(p_.center[ray.axis], d * Vec3::Unit(across), p_.radius, t0, t1)) return;
    const auto radial = [&](double t) {
        Vec3 n = Vec3::Zero();
        n[ray.axis] = (t - p_.center[ray.axis]) / p_.radius;
        n[across] = d / p_.radius;
        return n;
    };
    out.push_back({{t0, radial(t0), p_.side_surface}, {t1, radial(t1), p_.side_surface}});
}

Sphere::Sphere(const Vec3& center, double radius, std::int32_t surface)
    : center_(center), radius_(radius), surface_(surface) {
    if (!(radius > 0.0)) throw InvalidInput("sphere radius must be positive");
}

Box3 Sphere::bounds() const { return Box3(center_.array() - radius_, center_.array() + radius_); }

void Sphere::intersect(const Ray& ray, std::vector<Interval>& out) const {
    Vec3 offset = ray.origin - center_;
    offset[ray.axis] = 0.0;
    double t0, t1;
    if (!chord(center_[ray.axis], offset, radius_, t0, t1)) return;
    const auto normal = [&](double t) { return Vec3((ray.point(t) - center_) / radius_); };
    out.push_back({{t0, normal(t0), surface_}, {t1, normal(t1), surface_}});
}

}  // namespace resharp::sim
