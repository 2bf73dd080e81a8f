#pragma once
/// Primitive solids with exact ray intersection: convex polytopes (and boxes as a special case),
/// finite z-axis cylinders and spheres. Enough to build test shapes by sampling one and
/// subtracting others (CSG difference through sim::subtract).

#include <cstdint>
#include <vector>

#include "resharp/sim/tridexel.h"

namespace resharp::sim {

/// One bounding plane of a convex polytope: points x with normal·x <= offset are inside.
struct HalfSpace {
    Vec3 normal;           ///< unit outward normal
    double offset = 0.0;   ///< normal·x on the plane, mm
    std::int32_t surface;  ///< id given to crossings of this face
};

/// The intersection of half-spaces; bounded (the constructor checks).
class ConvexPolytope final : public Solid {
public:
    /// \throws InvalidInput if a normal is not unit length or the intersection is empty or
    /// unbounded.
    explicit ConvexPolytope(std::vector<HalfSpace> faces);

    Box3 bounds() const override { return bounds_; }
    void intersect(const Ray& ray, std::vector<Interval>& out) const override;
    const std::vector<HalfSpace>& faces() const { return faces_; }

private:
    std::vector<HalfSpace> faces_;
    Box3 bounds_;
};

/// Face ids of an axis-aligned box, added to its first id: -x, +x, -y, +y, -z, +z.
enum BoxFace : int { kMinX = 0, kMaxX, kMinY, kMaxY, kMinZ, kMaxZ };

/// The axis-aligned box as a polytope; face k (BoxFace) gets id first_surface + k.
/// \throws InvalidInput if the box is empty.
ConvexPolytope axis_box(const Box3& box, std::int32_t first_surface);

/// A finite cylinder with its axis along z.
class ZCylinder final : public Solid {
public:
    struct Params {
        Eigen::Vector2d center{0.0, 0.0};  ///< axis position (x, y), mm
        double radius = 1.0;               ///< mm, > 0
        double z_min = 0.0, z_max = 1.0;   ///< bottom and top planes, mm, z_min < z_max
        std::int32_t side_surface = 0;     ///< id of the curved face
        std::int32_t bottom_surface = 1;   ///< id of the z = z_min disk
        std::int32_t top_surface = 2;      ///< id of the z = z_max disk
    };
    /// \throws InvalidInput if radius or height is not positive.
    explicit ZCylinder(const Params& params);

    Box3 bounds() const override;
    void intersect(const Ray& ray, std::vector<Interval>& out) const override;

private:
    Params p_;
};

/// A ball.
class Sphere final : public Solid {
public:
    /// \throws InvalidInput if the radius is not positive.
    Sphere(const Vec3& center, double radius, std::int32_t surface);

    Box3 bounds() const override;
    void intersect(const Ray& ray, std::vector<Interval>& out) const override;

private:
    Vec3 center_;
    double radius_;
    std::int32_t surface_;
};

}  // namespace resharp::sim
