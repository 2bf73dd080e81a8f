#include "resharp/mesh/geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "resharp/core/assert.h"
#include "resharp/core/parallel.h"

namespace resharp {

namespace {

/// The normal of face f scaled by twice its area. Inline: surface_normals() takes it for every
/// face, and as a call it cost mech 4.8 M instructions more.
inline Vec3 area_vector(const Mesh& mesh, std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.positions[t[0]];
    return (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
}

Vec3 unit_or_zero(const Vec3& n) {
    const double length = n.norm();
    return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

}  // namespace

Vec3 triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    return unit_or_zero((b - a).cross(c - a));
}

double longest_edge_squared(const Mesh& mesh, Index f) {
    return longest_edge_squared(mesh.positions, mesh.triangles[f]);
}

double longest_edge_squared(std::span<const Vec3> x, const Triangle& t) {
    return std::max({(x[t[1]] - x[t[0]]).squaredNorm(), (x[t[2]] - x[t[1]]).squaredNorm(),
                     (x[t[0]] - x[t[2]]).squaredNorm()});
}

double corner_angle(const Mesh& mesh, Index f, int k) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& p = mesh.positions[t[k]];
    const Vec3 u = mesh.positions[t[(k + 1) % 3]] - p;
    const Vec3 w = mesh.positions[t[(k + 2) % 3]] - p;
    // atan2 of |cross| and dot keeps full precision for the tiny and the obtuse angles.
    return std::atan2(u.cross(w).norm(), u.dot(w));
}

std::vector<Vec3> face_normals(const Mesh& mesh) {
    std::vector<Vec3> normals(mesh.face_count());
    for_each_index(normals.size(), 8192,
                   [&](std::size_t f) { normals[f] = unit_or_zero(area_vector(mesh, f)); });
    return normals;
}

SurfaceNormals surface_normals(const Mesh& mesh, const Connectivity& connectivity) {
    SurfaceNormals n{std::vector<Vec3>(mesh.face_count()), std::vector<Vec3>(mesh.vertex_count())};
    // The face slots hold the area vectors until every vertex has summed those of its ring (in
    // ring order, so the sums do not depend on the thread count); then they are normalised.
    for_each_index(n.face.size(), 8192, [&](std::size_t f) { n.face[f] = area_vector(mesh, f); });
    for_each_index(n.vertex.size(), 4096, [&](std::size_t v) {
        Vec3 sum = Vec3::Zero();
        for (Index f : connectivity.faces_around(static_cast<Index>(v))) sum += n.face[f];
        n.vertex[v] = unit_or_zero(sum);
    });
    for_each_index(n.face.size(), 8192,
                   [&](std::size_t f) { n.face[f] = unit_or_zero(n.face[f]); });
    return n;
}

std::vector<Index> faces_with_moved_corner(const Mesh& mesh, const Connectivity& connectivity,
                                           std::span<const std::uint8_t> moved,
                                           std::span<const Index> also) {
    std::vector<std::uint8_t> flagged(mesh.face_count(), 0);
    for (Index v = 0; v < moved.size(); ++v) {
        if (!moved[v]) continue;
        for (Index f : connectivity.faces_around(v)) flagged[f] = 1;
    }
    for (Index f : also) flagged[f] = 1;
    std::vector<Index> faces;
    for (Index f = 0; f < flagged.size(); ++f) {
        if (flagged[f]) faces.push_back(f);
    }
    return faces;
}

namespace {

/// `unmoved` with the vertex normals of the corners of `changed` (faces) computed again, each
/// summing its ring's area vectors in ring order, as surface_normals() does: the same bits.
std::vector<Vec3> vertex_normals_of_changed_faces(const Mesh& mesh,
                                                  const Connectivity& connectivity,
                                                  std::vector<Vec3> unmoved,
                                                  const std::vector<Index>& changed) {
    std::vector<Index> vertices;
    std::vector<std::uint8_t> vertex_changed(mesh.vertex_count(), 0);
    for (Index f : changed) {
        for (Index v : mesh.triangles[f]) {
            if (!vertex_changed[v]) vertices.push_back(v);
            vertex_changed[v] = 1;
        }
    }
    for_each_index(vertices.size(), 1024, [&](std::size_t i) {
        Vec3 sum = Vec3::Zero();
        for (Index f : connectivity.faces_around(vertices[i])) sum += area_vector(mesh, f);
        unmoved[vertices[i]] = unit_or_zero(sum);
    });
    return unmoved;
}

}  // namespace

SurfaceNormals surface_normals_after_moves(const Mesh& mesh, const Connectivity& connectivity,
                                           SurfaceNormals unmoved,
                                           std::span<const std::uint8_t> moved) {
    const std::vector<Index> faces = faces_with_moved_corner(mesh, connectivity, moved);
    unmoved.vertex =
        vertex_normals_of_changed_faces(mesh, connectivity, std::move(unmoved.vertex), faces);
    for_each_index(faces.size(), 4096, [&](std::size_t i) {
        unmoved.face[faces[i]] = unit_or_zero(area_vector(mesh, faces[i]));
    });
    return unmoved;
}

std::vector<Vec3> vertex_normals(const Mesh& mesh, const Connectivity& connectivity) {
    return surface_normals(mesh, connectivity).vertex;
}

double angle_deg(const Vec3& a, const Vec3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi;
}

int corner_of(const Triangle& t, Index v) {
    if (t[0] == v) return 0;
    if (t[1] == v) return 1;
    RESHARP_ASSERT(t[2] == v);
    return 2;
}

namespace {
double squared_distance_to_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double length = ab.squaredNorm();
    const double t = length > 0.0 ? std::clamp((x - a).dot(ab) / length, 0.0, 1.0) : 0.0;
    return (a + t * ab - x).squaredNorm();
}
}  // namespace

double squared_distance_to_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ax = x - a;
    const Vec3 n = ab.cross(ac);
    const double area2 = n.squaredNorm();
    if (area2 > 0.0) {
        // Inside the prism over the face: the distance to its plane.
        const Vec3 bx = x - b, cx = x - c;
        const bool inside = n.dot(ab.cross(ax)) >= 0.0 && n.dot((c - b).cross(bx)) >= 0.0 &&
                            n.dot((a - c).cross(cx)) >= 0.0;
        if (inside) {
            const double height = n.dot(ax);
            return height * height / area2;
        }
    }
    // Otherwise (or degenerate): the closest of the three edges.
    return std::min({squared_distance_to_segment(x, a, b), squared_distance_to_segment(x, b, c),
                     squared_distance_to_segment(x, c, a)});
}

}  // namespace resharp
