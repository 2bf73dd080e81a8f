// OpenVDB as a mesher the project did not write: solids sampled by the simulator on a fine grid
// are voxelised into a level set (openvdb::tools::meshToLevelSet) and meshed by
// openvdb::tools::volumeToMesh at adaptivity 0 (dual: one vertex per voxel, near the surface but
// not on it), then restored; the restoration must finish and do no harm (issue 11's criteria).
// One translation unit on purpose: OpenVDB's headers are heavy to compile.

#include <gtest/gtest.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <functional>
#include <string>
#include <vector>

#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"
#include "resharp/pipeline/restore.h"
#include "support/grid_shapes.h"
#include "support/invariants.h"

namespace resharp {
namespace {

constexpr double kPitch = 0.5;  // h: the voxel size OpenVDB meshes at, mm
constexpr int kFine = 8;        // the simulated mesh is sampled at h / kFine

/// Takes a closed, outward mesh (#V, #F) and gives its narrow-band level set (3 voxels each side)
/// on voxels of size `pitch` whose centres lie at integer multiples of it.
openvdb::FloatGrid::Ptr level_set(const Mesh& mesh, double pitch) {
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.vertex_count());
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x(), p.y(), p.z());
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.face_count());
    for (const Triangle& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    const auto transform = openvdb::math::Transform::createLinearTransform(pitch);
    return openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles);
}

/// Takes a level set and gives volumeToMesh's surface at adaptivity 0 as triangles: each quad
/// split along its shorter diagonal, turned so that normals point out of the solid (OpenVDB
/// winds its quads the other way).
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

/// Six times the volume the mesh encloses: positive when its normals point out.
double six_volume(const Mesh& mesh) {
    double volume = 0.0;
    for (const Triangle& t : mesh.triangles) {
        const auto& x = mesh.positions;
        volume += x[t[0]].dot(x[t[1]].cross(x[t[2]]));
    }
    return volume;
}

struct Solid {
    std::string name;
    std::function<test::SampledShape(double)> sample;  ///< the shape sampled at a pitch
};

TEST(OpenVdbMesher, SimulatedSolidsRestoreWithoutHarm) {
    openvdb::initialize();
    const std::vector<Solid> solids = {
        {"box", test::sampled_box},
        {"L-block", test::sampled_l_block},
        {"drilled plate", [](double pitch) { return test::sampled_drilled_plate(pitch); }},
        {"rotated box", test::sampled_rotated_box},
    };
    const RestoreOptions options;
    for (const Solid& solid : solids) {
        SCOPED_TRACE(solid.name);
        const test::SampledShape fine = solid.sample(kPitch / kFine);
        const Mesh input = dual_mesh(*level_set(fine.mesh, kPitch));
        ASSERT_GT(input.face_count(), 100u);
        ASSERT_GT(six_volume(input), 0.0);  // outward, as restore() expects
        const RestoreResult r = restore(input, options);
        EXPECT_FALSE(r.report.output_unchanged);
        EXPECT_GT(r.report.edge_points_inserted, 0u);
        test::expect_no_harm(input, r, options);
    }
}

}  // namespace
}  // namespace resharp
