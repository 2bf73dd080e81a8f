#pragma once
/// Shapes meshed the way a grid-based machining simulator meshes them (tri-dexel sampling and
/// marching cubes, resharp::sim), with the exact answer: every vertex lies on the true surface and
/// carries its exact normal and surface id; the exact faces, sharp edges and corners are listed so
/// tests can measure restored points against them.
///
/// Grid nodes sit at integer multiples of the pitch; no face of these shapes lies on a grid plane
/// at the default pitch 0.5 mm (so every sharp edge becomes a chamfer band, never a mesh edge).

#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "resharp/mesh/mesh.h"
#include "resharp/sim/marching_cubes.h"

namespace resharp::test {

/// One exact face of a test shape (the whole plane or cylinder it lies on).
struct ExactSurface {
    enum class Kind { Plane, Cylinder };
    Kind kind = Kind::Plane;
    Vec3 normal = Vec3::UnitZ();     ///< Plane: unit outward normal
    double offset = 0.0;             ///< Plane: normal·x on the plane, mm
    Eigen::Vector2d axis{0.0, 0.0};  ///< Cylinder: (x, y) of its vertical axis, mm
    double radius = 0.0;             ///< Cylinder radius, mm
    bool is_hole = true;             ///< Cylinder: material outside it (normals point to the axis)

    /// Distance from p to the plane or cylinder.
    double distance(const Vec3& p) const;
    /// Outward unit normal of the shape at the point of this surface nearest p.
    Vec3 normal_at(const Vec3& p) const;
};

/// A sharp edge of a test shape: a straight segment or a horizontal circle.
struct ExactEdge {
    enum class Kind { Segment, Circle };
    Kind kind = Kind::Segment;
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();  ///< Segment ends
    Vec3 center = Vec3::Zero();               ///< Circle centre (the circle lies at z = center.z)
    double radius = 0.0;                      ///< Circle radius
    std::int32_t surface_a = -1, surface_b = -1;  ///< ids of the two faces meeting here
    bool is_concave = false;                      ///< true for an inner (valley) edge

    /// Distance from p to the edge curve.
    double distance(const Vec3& p) const;
};

/// A shape sampled on a tri-dexel grid and meshed, with its exact description.
struct SampledShape {
    Mesh mesh;                                      ///< closed, manifold, outward oriented
    std::vector<Vec3> exact_normals;                ///< #V exact outward normals
    std::vector<std::int32_t> surface_ids;          ///< #V keys of `surfaces`
    double pitch = 0.5;                             ///< grid pitch h, mm
    double scale = 1.0;                             ///< largest extent of the shape, mm
    std::map<std::int32_t, ExactSurface> surfaces;  ///< every face, by surface id
    std::vector<ExactEdge> edges;                   ///< every sharp edge
    std::vector<Vec3> corners;  ///< every corner (where three or more faces meet)
    std::function<double(const Vec3&)> distance_to_surface;  ///< exact, unsigned, mm
    sim::MeshingStats stats;
};

/// The box [0.37, 10.21] x [0.29, 8.13] x [0.41, 6.07] mm: faces 0..5 are -x, +x, -y, +y, -z,
/// +z; 12 convex edges (the box's edges), 8 corners.
SampledShape sampled_box(double pitch = 0.5);

/// An L-block: the box [0.37, 12.21] x [0.29, 8.13] x [0.41, 8.07] (faces 0..5 as for the box)
/// with the notch x > 6.33, z > 4.19 removed. The notch adds face 6 (the step wall x = 6.33,
/// normal +x) and face 10 (the step floor z = 4.19, normal +z). In the xz-profile
/// (0.37,0.41) (12.21,0.41) (12.21,4.19) (6.33,4.19) (6.33,8.07) (0.37,8.07) every vertex is an
/// edge along y from y = 0.29 to 8.13, the one at (6.33, 4.19) concave; the profile's six sides at
/// y = 0.29 and y = 8.13 are the other twelve edges. 12 corners.
SampledShape sampled_l_block(double pitch = 0.5);

/// A plate [0.37, 14.21] x [0.29, 12.13] x [0.41, 4.07] (faces 0..5) drilled through by a
/// vertical hole of radius 3.08 around (7.23, 6.17) (face 6, the hole wall). Edges: the 12 box
/// edges and the two circles where the hole meets the top (z = 4.07) and bottom (z = 0.41) faces;
/// 8 corners. Meshed by `mesher` (the exact data are those of the nearest surface point for the
/// meshers that place vertices off the surface).
SampledShape sampled_drilled_plate(double pitch = 0.5,
                                   sim::Mesher mesher = sim::Mesher::MarchingCubes);

/// A box of half-sizes (5.13, 3.92, 2.87) centred at (0.11, 0.07, 0.13) in its own frame,
/// rotated 30° about x and then 30° about y: x_world = Ry(30°) Rx(30°) x_local + centre. Faces 0..5
/// are its -x, +x, -y, +y, -z, +z faces in the local frame; 12 edges, 8 corners. No chamfer runs
/// along a grid axis.
SampledShape sampled_rotated_box(double pitch = 0.5);

}  // namespace resharp::test
