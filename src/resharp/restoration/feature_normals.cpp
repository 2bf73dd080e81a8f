#include "resharp/restoration/feature_normals.h"

#include <tbb/parallel_for.h>

#include "resharp/mesh/geometry.h"

namespace resharp {
namespace {

bool lies_on_patch(const Triangle& t, const std::vector<Index>& vertex_patch, Index patch) {
    return vertex_patch[t[0]] == patch && vertex_patch[t[1]] == patch &&
           vertex_patch[t[2]] == patch;
}

Vec3 patch_normal(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                  const std::vector<Index>& face_patch, const std::vector<Index>& vertex_patch,
                  Index v, bool whole_faces_only) {
    const Index patch = vertex_patch[v];
    Vec3 sum = Vec3::Zero();
    for (Index f : c.faces_around(v)) {
        if (face_patch[f] != patch) continue;
        if (whole_faces_only && !lies_on_patch(mesh.triangles[f], vertex_patch, patch)) continue;
        sum += corner_angle(mesh, f, corner_of(mesh.triangles[f], v)) * normals[f];
    }
    const double length = sum.norm();
    return length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
}

/// Eq. 5.1 at v over its own patch, preferring faces that lie wholly on it.
Vec3 own_patch_normal(const Mesh& mesh, const Connectivity& c, const std::vector<Vec3>& normals,
                      const std::vector<Index>& face_patch, const std::vector<Index>& vertex_patch,
                      Index v) {
    const Vec3 n = patch_normal(mesh, c, normals, face_patch, vertex_patch, v, true);
    return n.isZero(0.0) ? patch_normal(mesh, c, normals, face_patch, vertex_patch, v, false) : n;
}

/// For a vertex with no face on its own patch (all its faces lie in bands): the mean of the
/// own-patch normals of its neighbours on the same patch.
Vec3 neighbours_patch_normal(const Mesh& mesh, const Connectivity& c,
                             const std::vector<Vec3>& normals, const std::vector<Index>& face_patch,
                             const std::vector<Index>& vertex_patch, Index v) {
    Vec3 sum = Vec3::Zero();
    for_each_ring_vertex(mesh, c, v, [&](Index q) {
        if (vertex_patch[q] == vertex_patch[v]) {
            sum += own_patch_normal(mesh, c, normals, face_patch, vertex_patch, q);
        }
    });
    const double length = sum.norm();
    return length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
}

}  // namespace

std::vector<Vec3> feature_normals(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const std::vector<Index>& face_patch,
                                  const std::vector<Index>& vertex_patch,
                                  const BandClassification& bands) {
    std::vector<std::uint8_t> needed(mesh.vertex_count(), 0);
    for (Index f = 0; f < mesh.face_count(); ++f) {
        if (bands.face_role[f] == BandRole::None) continue;
        for (Index v : mesh.triangles[f]) needed[v] = 1;
    }
    std::vector<Vec3> result(mesh.vertex_count(), Vec3::Zero());
    tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(mesh.vertex_count()), 4096),
                      [&](const auto& range) {
                          for (Index v = range.begin(); v != range.end(); ++v) {
                              if (!needed[v] || vertex_patch[v] == kNoIndex) continue;
                              Vec3 n = own_patch_normal(mesh, connectivity, face_normals,
                                                        face_patch, vertex_patch, v);
                              if (n.isZero(0.0)) {
                                  n = neighbours_patch_normal(mesh, connectivity, face_normals,
                                                              face_patch, vertex_patch, v);
                              }
                              result[v] = n;
                          }
                      });
    return result;
}

}  // namespace resharp
