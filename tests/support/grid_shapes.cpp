#include "support/grid_shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "resharp/sim/solids.h"

namespace resharp::test {
namespace {

using sim::Box3;

constexpr double kDeg = std::numbers::pi / 180.0;

/// Distance from p to the surface of an axis-aligned box, inside or out.
double box_surface_distance(const Box3& box, const Vec3& p) {
    if (box.contains(p)) {
        const Vec3 to_min = p - box.min(), to_max = box.max() - p;
        return std::min(to_min.minCoeff(), to_max.minCoeff());
    }
    return box.exteriorDistance(p);
}

double point_distance(const Box3& box, const Vec3& p) { return box.exteriorDistance(p); }

ExactSurface plane(const Vec3& normal, double offset) {
    ExactSurface s;
    s.kind = ExactSurface::Kind::Plane;
    s.normal = normal;
    s.offset = offset;
    return s;
}

/// The faces 0..5 (-x, +x, -y, +y, -z, +z) of a box in a frame `rotation`, centred at `centre`.
void add_box_faces(SampledShape& shape, const Eigen::Matrix3d& rotation, const Vec3& centre,
                   const Vec3& half) {
    for (int a = 0; a < 3; ++a) {
        for (int side = 0; side < 2; ++side) {
            const Vec3 n = (side == 0 ? -1.0 : 1.0) * rotation.col(a);
            shape.surfaces[2 * a + side] = plane(n, n.dot(centre) + half[a]);
        }
    }
}

ExactEdge segment(const Vec3& a, const Vec3& b, std::int32_t sa, std::int32_t sb,
                  bool concave = false) {
    ExactEdge e;
    e.a = a;
    e.b = b;
    e.surface_a = sa;
    e.surface_b = sb;
    e.is_concave = concave;
    return e;
}

/// The 12 edges and 8 corners of a box in frame `rotation`; face ids as in add_box_faces.
void add_box_edges(SampledShape& shape, const Eigen::Matrix3d& rotation, const Vec3& centre,
                   const Vec3& half) {
    const auto corner = [&](int bits) {
        Vec3 local;
        for (int a = 0; a < 3; ++a) local[a] = ((bits >> a) & 1) ? half[a] : -half[a];
        return Vec3(rotation * local + centre);
    };
    for (int bits = 0; bits < 8; ++bits) shape.corners.push_back(corner(bits));
    for (int d = 0; d < 3; ++d) {
        const int b = (d + 1) % 3, c = (d + 2) % 3;
        for (int sb = 0; sb < 2; ++sb) {
            for (int sc = 0; sc < 2; ++sc) {
                const int from = (sb << b) | (sc << c);
                shape.edges.push_back(
                    segment(corner(from), corner(from | (1 << d)), 2 * b + sb, 2 * c + sc));
            }
        }
    }
}

/// Meshes the grid and copies the mesh and oracle into the shape.
void mesh_into(SampledShape& shape, const sim::DexelGrid& grid,
               sim::Mesher mesher = sim::Mesher::MarchingCubes) {
    sim::OracleMesh meshed = sim::mesh_dexels(grid, {.mesher = mesher});
    shape.mesh = std::move(meshed.mesh);
    shape.exact_normals = std::move(meshed.normals);
    shape.surface_ids = std::move(meshed.surface_ids);
    shape.stats = meshed.stats;
    shape.pitch = grid.spec.pitch;
}

}  // namespace

double ExactSurface::distance(const Vec3& p) const {
    if (kind == Kind::Plane) return std::abs(normal.dot(p) - offset);
    return std::abs((p.head<2>() - axis).norm() - radius);
}

Vec3 ExactSurface::normal_at(const Vec3& p) const {
    if (kind == Kind::Plane) return normal;
    const Eigen::Vector2d radial = (p.head<2>() - axis).normalized();
    const Vec3 out(radial.x(), radial.y(), 0.0);
    return is_hole ? Vec3(-out) : out;
}

double ExactEdge::distance(const Vec3& p) const {
    if (kind == Kind::Circle) {
        const double radial = (p.head<2>() - center.head<2>()).norm() - radius;
        return std::hypot(radial, p.z() - center.z());
    }
    const Vec3 ab = b - a;
    const double s = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + s * ab)).norm();
}

SampledShape sampled_box(double pitch) {
    const Box3 box(Vec3(0.37, 0.29, 0.41), Vec3(10.21, 8.13, 6.07));
    SampledShape shape;
    add_box_faces(shape, Eigen::Matrix3d::Identity(), box.center(), box.sizes() / 2);
    add_box_edges(shape, Eigen::Matrix3d::Identity(), box.center(), box.sizes() / 2);
    shape.scale = box.sizes().maxCoeff();
    shape.distance_to_surface = [box](const Vec3& p) { return box_surface_distance(box, p); };
    const sim::ConvexPolytope solid = sim::axis_box(box, 0);
    mesh_into(shape, sim::sample_solid(sim::grid_enclosing(box, pitch), solid));
    return shape;
}

SampledShape sampled_l_block(double pitch) {
    const Vec3 lo(0.37, 0.29, 0.41), hi(12.21, 8.13, 8.07);
    const double step_x = 6.33, step_z = 4.19;
    const Box3 block(lo, hi);
    const Box3 notch(Vec3(step_x, lo.y() - 1, step_z), Vec3(hi.x() + 1, hi.y() + 1, hi.z() + 1));
    SampledShape shape;
    add_box_faces(shape, Eigen::Matrix3d::Identity(), block.center(), block.sizes() / 2);
    shape.surfaces[6] = plane(Vec3::UnitX(), step_x);
    shape.surfaces[10] = plane(Vec3::UnitZ(), step_z);

    // The profile in xz, counter-clockwise seen from -y, with the face id of each side.
    const std::vector<Eigen::Vector2d> profile{{lo.x(), lo.z()}, {hi.x(), lo.z()},
                                               {hi.x(), step_z}, {step_x, step_z},
                                               {step_x, hi.z()}, {lo.x(), hi.z()}};
    const std::vector<std::int32_t> side_face{4, 1, 10, 6, 5, 0};  // side k runs from k to k+1
    const auto at = [](const Eigen::Vector2d& xz, double y) { return Vec3(xz.x(), y, xz.y()); };
    for (std::size_t k = 0; k < profile.size(); ++k) {
        const std::size_t next = (k + 1) % profile.size();
        const std::int32_t before = side_face[(k + profile.size() - 1) % profile.size()];
        shape.edges.push_back(
            segment(at(profile[k], lo.y()), at(profile[k], hi.y()), before, side_face[k], k == 3));
        for (const auto& [y, face] : {std::pair{lo.y(), 2}, std::pair{hi.y(), 3}}) {
            shape.edges.push_back(
                segment(at(profile[k], y), at(profile[next], y), side_face[k], face));
        }
        shape.corners.push_back(at(profile[k], lo.y()));
        shape.corners.push_back(at(profile[k], hi.y()));
    }
    shape.scale = block.sizes().maxCoeff();
    const Box3 lower(lo, Vec3(hi.x(), hi.y(), step_z)),
        upper(Vec3(lo.x(), lo.y(), step_z), Vec3(step_x, hi.y(), hi.z()));
    shape.distance_to_surface = [=](const Vec3& p) {
        const bool inside = block.contains(p) && !(p.x() > step_x && p.z() > step_z);
        if (inside) return std::min(box_surface_distance(block, p), point_distance(notch, p));
        return std::min(point_distance(lower, p), point_distance(upper, p));
    };

    const sim::ConvexPolytope solid = sim::axis_box(block, 0);
    const sim::ConvexPolytope removed = sim::axis_box(notch, 6);
    sim::DexelGrid grid = sim::sample_solid(sim::grid_enclosing(block, pitch), solid);
    sim::subtract(grid, removed);
    mesh_into(shape, grid);
    return shape;
}

SampledShape sampled_drilled_plate(double pitch, sim::Mesher mesher) {
    const Box3 plate(Vec3(0.37, 0.29, 0.41), Vec3(14.21, 12.13, 4.07));
    const Eigen::Vector2d axis(7.23, 6.17);
    const double radius = 3.08;
    SampledShape shape;
    add_box_faces(shape, Eigen::Matrix3d::Identity(), plate.center(), plate.sizes() / 2);
    add_box_edges(shape, Eigen::Matrix3d::Identity(), plate.center(), plate.sizes() / 2);
    ExactSurface hole;
    hole.kind = ExactSurface::Kind::Cylinder;
    hole.axis = axis;
    hole.radius = radius;
    hole.is_hole = true;
    shape.surfaces[6] = hole;
    for (const auto& [z, face] : {std::pair{plate.max().z(), 5}, std::pair{plate.min().z(), 4}}) {
        ExactEdge circle;
        circle.kind = ExactEdge::Kind::Circle;
        circle.center = Vec3(axis.x(), axis.y(), z);
        circle.radius = radius;
        circle.surface_a = face;
        circle.surface_b = 6;
        shape.edges.push_back(circle);
    }
    shape.scale = plate.sizes().maxCoeff();
    shape.distance_to_surface = [=](const Vec3& p) {
        const Eigen::Vector2d radial = p.head<2>() - axis;
        const double r = radial.norm();
        if (plate.contains(p) && r >= radius) {
            return std::min(box_surface_distance(plate, p), r - radius);
        }
        const Vec3 nearest_in_plate = p.cwiseMax(plate.min()).cwiseMin(plate.max());
        if ((nearest_in_plate.head<2>() - axis).norm() >= radius) {
            return (p - nearest_in_plate).norm();
        }
        // Over or in the hole: the nearest material is on the wall, at most at its rims.
        const Eigen::Vector2d direction =
            r > 0.0 ? Eigen::Vector2d(radial / r) : Eigen::Vector2d::UnitX();
        const double z = std::clamp(p.z(), plate.min().z(), plate.max().z());
        const Eigen::Vector2d on_wall = axis + radius * direction;
        return (p - Vec3(on_wall.x(), on_wall.y(), z)).norm();
    };

    const sim::ConvexPolytope solid = sim::axis_box(plate, 0);
    const sim::ZCylinder drill({.center = axis,
                                .radius = radius,
                                .z_min = plate.min().z() - 1.0,
                                .z_max = plate.max().z() + 1.0,
                                .side_surface = 6,
                                .bottom_surface = 7,
                                .top_surface = 8});
    sim::DexelGrid grid = sim::sample_solid(sim::grid_enclosing(plate, pitch), solid);
    sim::subtract(grid, drill);
    mesh_into(shape, grid, mesher);
    return shape;
}

SampledShape sampled_rotated_box(double pitch) {
    const Vec3 half(5.13, 3.92, 2.87), centre(0.11, 0.07, 0.13);
    const Eigen::Matrix3d rotation =
        (Eigen::AngleAxisd(30 * kDeg, Vec3::UnitY()) * Eigen::AngleAxisd(30 * kDeg, Vec3::UnitX()))
            .toRotationMatrix();
    SampledShape shape;
    add_box_faces(shape, rotation, centre, half);
    add_box_edges(shape, rotation, centre, half);
    shape.scale = 2 * half.maxCoeff();
    const Box3 local(-half, half);
    shape.distance_to_surface = [=](const Vec3& p) {
        return box_surface_distance(local, rotation.transpose() * (p - centre));
    };
    std::vector<sim::HalfSpace> faces;
    for (const auto& [id, surface] : shape.surfaces) {
        faces.push_back({surface.normal, surface.offset, id});
    }
    const sim::ConvexPolytope solid(std::move(faces));
    const Box3 bounds = solid.bounds();
    mesh_into(shape, sim::sample_solid(sim::grid_enclosing(bounds, pitch), solid));
    return shape;
}

}  // namespace resharp::test
