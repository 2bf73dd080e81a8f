#include "resharp/mesh/geometry.h"

#include <cmath>
#include <numbers>

#include <tbb/parallel_for.h>

#include "resharp/core/assert.h"

namespace resharp {

Vec3 triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const double length = n.norm();
    return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
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
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, normals.size(), 8192),
                      [&](const auto& range) {
                          for (std::size_t f = range.begin(); f != range.end(); ++f) {
                              const Triangle& t = mesh.triangles[f];
                              normals[f] = triangle_normal(mesh.positions[t[0]],
                                                           mesh.positions[t[1]],
                                                           mesh.positions[t[2]]);
                          }
                      });
    return normals;
}

std::vector<Vec3> vertex_normals(const Mesh& mesh, const Connectivity& connectivity) {
    std::vector<Vec3> result(mesh.vertex_count());
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, result.size(), 4096), [&](const auto& range) {
            for (std::size_t v = range.begin(); v != range.end(); ++v) {
                Vec3 sum = Vec3::Zero();  // twice the area-weighted sum
                for (Index f : connectivity.faces_around(static_cast<Index>(v))) {
                    const Triangle& t = mesh.triangles[f];
                    const Vec3& a = mesh.positions[t[0]];
                    sum += (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
                }
                const double length = sum.norm();
                result[v] = length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
            }
        });
    return result;
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

}  // namespace resharp
