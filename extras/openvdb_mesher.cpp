#include "openvdb_mesher.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <vector>

namespace resharp::extras {
namespace {

openvdb::FloatGrid::Ptr level_set(const Mesh& mesh, double pitch, const Vec3& origin) {
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.vertex_count());
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x(), p.y(), p.z());
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.face_count());
    for (const Triangle& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    // Index (i, j, k) at origin + (i, j, k) * pitch: voxel centres, the samples volumeToMesh
    // meshes between, on the grid the caller names.
    const auto transform = openvdb::math::Transform::createLinearTransform(pitch);
    transform->postTranslate(openvdb::Vec3d(origin.x(), origin.y(), origin.z()));
    return openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles);
}

Mesh dual_mesh(const openvdb::FloatGrid& grid) {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(grid, points, triangles, quads, 0.0, 0.0);
    Mesh mesh;
    mesh.positions.reserve(points.size());
    for (const openvdb::Vec3s& p : points) mesh.positions.emplace_back(p.x(), p.y(), p.z());
    auto add = [&](Index a, Index b, Index c) { mesh.triangles.push_back({a, c, b}); };
    for (const openvdb::Vec3I& t : triangles) add(t[0], t[1], t[2]);
    for (const openvdb::Vec4I& q : quads) {
        const auto& x = mesh.positions;
        if ((x[q[0]] - x[q[2]]).squaredNorm() <= (x[q[1]] - x[q[3]]).squaredNorm()) {
            add(q[0], q[1], q[2]);
            add(q[0], q[2], q[3]);
        } else {
            add(q[0], q[1], q[3]);
            add(q[1], q[2], q[3]);
        }
    }
    return mesh;
}

}  // namespace

Mesh openvdb_dual_mesh(const Mesh& mesh, double pitch, const Vec3& origin) {
    openvdb::initialize();  // idempotent
    return dual_mesh(*level_set(mesh, pitch, origin));
}

}  // namespace resharp::extras
