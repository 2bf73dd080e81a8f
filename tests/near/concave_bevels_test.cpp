// near/concave_bevels.h on meshes without bevels: surface nets put one vertex in the cell a
// concave edge crosses, on the edge's two faces' junction, and leave no strip across the corner.
// (OpenVDB's bevels: tests/near/openvdb_placement_test.cpp.)

#include "resharp/near/concave_bevels.h"

#include <gtest/gtest.h>

#include "resharp/mesh/connectivity.h"
#include "resharp/pipeline/restore.h"
#include "support/small_parts.h"

namespace resharp {
namespace {

TEST(ConcaveBevels, SurfaceNetsMeshesHaveNoneToDissolve) {
    for (const test::SmallPart part : test::kSmallParts) {
        SCOPED_TRACE(std::string(test::to_string(part)));
        const Mesh mesh = test::small_part(part, 0.5, sim::Mesher::SurfaceNets);
        const sim::GridSpec spec = test::small_part_grid(part, 0.5);
        const Detection d = detect_bands(mesh, build_connectivity(mesh), {});
        const BevelDissolution b =
            without_concave_bevels(d.surface(mesh), d.features, d.bands, {spec.pitch, spec.origin});
        EXPECT_EQ(b.bevels, 0u);
        EXPECT_EQ(b.features.vertex_patch, d.features.vertex_patch);
        EXPECT_EQ(b.features.face_patch, d.features.face_patch);
    }
}

}  // namespace
}  // namespace resharp
