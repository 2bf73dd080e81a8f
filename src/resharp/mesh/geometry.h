#pragma once
/// Per-face and per-vertex geometric quantities every stage needs.

#include <cstdint>
#include <span>
#include <vector>

#include "resharp/core/types.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

/// Unit normal of triangle (a, b, c) by the right-hand rule; zero for a degenerate triangle.
Vec3 triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c);

/// Squared length of face f's longest edge: the face's size, which relative tolerances scale by.
double longest_edge_squared(const Mesh& mesh, Index f);
/// The same of triangle t at `positions` (a mesh's faces at other places of its vertices).
double longest_edge_squared(std::span<const Vec3> positions, const Triangle& t);

/// Interior angle (radians) at corner k of face f.
double corner_angle(const Mesh& mesh, Index f, int k);

/// Per face (#F): unit normals, zero for degenerate faces.
std::vector<Vec3> face_normals(const Mesh& mesh);

/// Face and vertex normals together, as every stage after mesh building takes them.
struct SurfaceNormals {
    std::vector<Vec3> face;    ///< per face (#F): as face_normals gives them
    std::vector<Vec3> vertex;  ///< per vertex (#V): as vertex_normals gives them
};

/// Takes the mesh and its connectivity; gives both kinds of normal, computing each face's cross
/// product once where the two functions above would compute it four times.
SurfaceNormals surface_normals(const Mesh& mesh, const Connectivity& connectivity);

/// The faces of `mesh` with a corner flagged in `moved` (#V), or listed in `also`, ascending,
/// each once. Only the moved vertices' rings are walked, then the flags once.
std::vector<Index> faces_with_moved_corner(const Mesh& mesh, const Connectivity& connectivity,
                                           std::span<const std::uint8_t> moved,
                                           std::span<const Index> also = {});

/// surface_normals() of `mesh` from `unmoved`, those of a mesh with the same faces whose
/// vertices flagged in `moved` (#V) sat elsewhere: only the faces with a moved corner and the
/// vertices of those faces are computed again, the same bits as surface_normals() gives. A near
/// mesh's vertex moves touch a few percent of its faces. Either way: it gives a moved mesh's
/// normals back to the mesh they were moved from, the same bits.
SurfaceNormals surface_normals_after_moves(const Mesh& mesh, const Connectivity& connectivity,
                                           SurfaceNormals unmoved,
                                           std::span<const std::uint8_t> moved);

/// Per vertex (#V): area-weighted mean of the incident face normals, normalised; zero where
/// every incident face is degenerate. Area weights need no trigonometry, which matters at a
/// million corners; eq. 5.1's angle weights are kept for the feature normals that place points.
std::vector<Vec3> vertex_normals(const Mesh& mesh, const Connectivity& connectivity);

/// Angle in degrees between two unit vectors, robust near 0 and 180.
double angle_deg(const Vec3& a, const Vec3& b);

/// Position of v within face f (0, 1 or 2). f must contain v.
int corner_of(const Triangle& t, Index v);

/// Squared distance from x to the closest point of triangle (a, b, c): to its plane where x
/// projects inside it, to the closest of its edges otherwise (and for a degenerate triangle).
double squared_distance_to_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace resharp
