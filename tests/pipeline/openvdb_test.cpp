// OpenVDB as a mesher the project did not write (extras/openvdb_mesher.h): solids sampled by the
// simulator on a fine grid are meshed by volumeToMesh at adaptivity 0, then restored; the
// restoration must finish and do no harm (issue 11's criteria).

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "openvdb_mesher.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/mesh/geometry.h"
#include "resharp/pipeline/restore.h"
#include "support/grid_shapes.h"
#include "support/invariants.h"

namespace resharp {
namespace {

constexpr double kPitch = 0.5;  // h: the voxel size OpenVDB meshes at, mm
constexpr int kFine = 8;        // the simulated mesh is sampled at h / kFine

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
        const Mesh input = extras::openvdb_dual_mesh(fine.mesh, kPitch);
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
