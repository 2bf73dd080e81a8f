#pragma once
/// Solids by constructive solid geometry (CSG), exact per ray: boxes, cylinders and cones
/// (frustums), spheres, tori and half-spaces, each placed by a rotation and a translation, and
/// combined by union, difference and intersection. A CsgSolid is a sim::Solid, so the tri-dexel
/// grid samples it (sample_solid) and the marching cubes mesher meshes it as it meshes a milled
/// part, every vertex exactly on the surface with its exact normal and surface id. It also
/// answers point membership and gives each of its surfaces as an implicit function, from which
/// the evaluation finds the true sharp edges (eval/exact_creases.h). The file format is in
/// csg_file.h.
///
/// Surface ids (docs/oracle.md): the primitives in depth-first order of the tree, each taking the
/// next ids: a box 6 (its own -x, +x, -y, +y, -z, +z faces), a cone or cylinder 3 (side, bottom
/// cap at z = 0, top cap), a sphere, a torus and a half-space 1.
///
/// Coincident faces (a boss standing on a plate, a cutter flush with a face) are settled by a
/// tolerance: after each boolean operation, gaps and pieces of a line shorter than
/// kCoincidence times the diagonal of the solid's bounding box are closed or dropped.

#include <Eigen/Geometry>
#include <cstdint>
#include <variant>
#include <vector>

#include "resharp/sim/tridexel.h"

namespace resharp::sim {

/// A rigid motion: x_outer = rotation * x_inner + translation.
struct Placement {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< orthonormal, determinant +1
    Vec3 translation = Vec3::Zero();                         ///< mm

    Vec3 apply(const Vec3& x) const { return rotation * x + translation; }
    Vec3 apply_inverse(const Vec3& x) const { return rotation.transpose() * (x - translation); }
    /// This motion after `inner`: x -> apply(inner.apply(x)).
    Placement operator*(const Placement& inner) const {
        return {rotation * inner.rotation, rotation * inner.translation + translation};
    }
};

/// The axis-aligned box [min, max] of its own frame, mm.
struct BoxShape {
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Ones();
};
/// A frustum along +z of its own frame, from z = 0 to z = length (mm), of radius radius_bottom at
/// z = 0 and radius_top at z = length: a cylinder when they are equal, a cone when one is 0.
struct ConeShape {
    double length = 1.0;
    double radius_bottom = 1.0;
    double radius_top = 1.0;
};
/// The ball of this radius (mm) about the origin.
struct SphereShape {
    double radius = 1.0;
};
/// The ring torus about the z axis: a tube of radius `minor` around the circle of radius `major`
/// in the plane z = 0 (mm, major > minor).
struct TorusShape {
    double major = 2.0;
    double minor = 1.0;
};
/// The half-space z <= 0 of its own frame (its face has outward normal +z). Unbounded: the solid
/// must be bounded by the operations over it (an intersection operand, a difference's
/// subtrahend).
struct HalfSpaceShape {};

using Shape = std::variant<BoxShape, ConeShape, SphereShape, TorusShape, HalfSpaceShape>;

enum class CsgOp { Primitive, Union, Difference, Intersection };

/// A node of the tree: a shape, or an operation over its operands.
struct CsgNode {
    CsgOp op = CsgOp::Primitive;
    Shape shape = BoxShape{};       ///< for CsgOp::Primitive
    std::vector<CsgNode> operands;  ///< for the operations; Difference: the first minus the rest
    Placement placement;            ///< puts this node, and all under it, in its parent's frame
};

/// Nesting the tree may have: every recursion over it is bounded by this.
inline constexpr int kMaxCsgDepth = 64;
/// Relative tolerance of coincident faces (see the top of this file).
inline constexpr double kCoincidence = 1e-9;

/// \throws InvalidInput naming the first bad size (a box with min not below max on every axis, a
/// length or radius not positive, a cone with both radii 0, a torus with major <= minor).
void check_shape(const Shape& shape);

/// What kind of implicit function a surface has.
enum class SurfaceKind { Plane, Cone, Sphere, Torus };

/// One surface of a CSG solid, as an implicit function of world position: zero on the surface,
/// negative inside its primitive; the gradient is its outward normal there, not always unit.
/// In the primitive's frame: Plane n . x - offset; Cone rho - (radius + slope z) with rho the
/// distance from the z axis; Sphere |x| - radius; Torus sqrt((rho - radius)^2 + z^2) - tube.
struct CsgSurface {
    SurfaceKind kind = SurfaceKind::Plane;
    Placement frame;                    ///< the primitive's frame in the world
    Vec3 plane_normal = Vec3::UnitZ();  ///< Plane: unit normal, primitive frame
    double offset = 0.0;                ///< Plane: n . x on the plane, mm
    double radius = 0.0;  ///< Cone: radius at z = 0; Sphere: radius; Torus: the major radius
    double slope = 0.0;   ///< Cone: radius gained per mm along z
    double tube = 0.0;    ///< Torus: the minor radius
    /// +1 where the solid's outward normal is the gradient's direction, -1 where the primitive
    /// is subtracted (an odd number of difference subtrahends above it).
    double orientation = 1.0;

    double value(const Vec3& p) const;
    Vec3 gradient(const Vec3& p) const;
    /// The solid's outward unit normal at p on this surface (orientation times the unit
    /// gradient); zero where the gradient vanishes (a cone's apex, a torus's axis).
    Vec3 normal(const Vec3& p) const;
};

/// A CSG tree ready for rays and points.
class CsgSolid final : public Solid {
public:
    /// \throws InvalidInput if a shape is bad (check_shape), a rotation is not a rotation, an
    /// operation has no operands, the tree is deeper than kMaxCsgDepth, or the solid is empty
    /// or unbounded.
    explicit CsgSolid(const CsgNode& root);

    /// The root's box: exact for each shape and for unions of shapes; an intersection keeps the
    /// overlap of its operands' boxes, a difference its first operand's, each cut by the
    /// half-spaces among its operands.
    Box3 bounds() const override { return nodes_.front().bounds; }
    void intersect(const Ray& ray, std::vector<Interval>& out) const override;
    /// Appends the sorted, disjoint solid intervals of the line origin + t * direction (unit
    /// direction, t in mm) with exact outward normals and surface ids.
    void intersect_line(const Vec3& origin, const Vec3& direction,
                        std::vector<Interval>& out) const;
    /// Whether p lies inside (points on the surface may go either way).
    bool contains(const Vec3& p) const;
    /// Per surface id (#surfaces).
    const std::vector<CsgSurface>& surfaces() const { return surfaces_; }

private:
    struct Node {
        CsgOp op = CsgOp::Primitive;
        Shape shape;
        Placement world;                 // Shape: its frame in the world
        Box3 bounds;                     // world box
        std::int32_t first_surface = 0;  // Shape: id of its first surface
        std::vector<std::size_t> operands;
    };

    std::size_t add(const CsgNode& node, const Placement& parent, double orientation, int depth);
    Box3 operation_bounds(const Node& node) const;
    void intersect_node(std::size_t node, const Vec3& origin, const Vec3& direction,
                        std::vector<Interval>& out) const;
    bool contains_node(std::size_t node, const Vec3& p) const;

    std::vector<Node> nodes_;  // nodes_[0] is the root
    std::vector<CsgSurface> surfaces_;
    double tolerance_ = 0.0;  // mm, kCoincidence times the bounds' diagonal
};

}  // namespace resharp::sim
