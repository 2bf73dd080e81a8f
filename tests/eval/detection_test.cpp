#include "resharp/eval/detection.h"

#include <gtest/gtest.h>

#include "resharp/core/errors.h"

namespace resharp::eval {
namespace {

// A fan of three triangles around vertex 0: vertices 1, 2 on surface 1 (normal +z), vertex 3
// on surface 2 (normal +x), vertex 4 on surface 3 (normal +y), vertex 0 on surface 1.
// Face (0, 1, 2): all on surface 1, none. Face (0, 2, 3): edges 2-3 and 3-0 cross: edge.
// Face (2, 3, 4): three surfaces pairwise 90 degrees apart: corner.
TEST(Detection, TrueRolesFromTheOracle) {
    const Mesh mesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0, 2, 0)},
                    {{0, 1, 2}, {0, 2, 3}, {2, 3, 4}}};
    const Oracle oracle{{Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitX(), Vec3::UnitY()},
                        {1, 1, 1, 2, 3}};
    const auto roles = true_band_roles(mesh, oracle);
    EXPECT_EQ(roles, (std::vector{BandRole::None, BandRole::Edge, BandRole::Corner}));
    // Normals 20 degrees apart are not a sharp junction at theta_s = 30.
    Oracle gentle = oracle;
    const double a = 20.0 * 3.141592653589793 / 180.0;
    gentle.normals[3] = Vec3(std::sin(a), 0, std::cos(a));
    gentle.normals[4] = Vec3(0, std::sin(a), std::cos(a));
    EXPECT_EQ(true_band_roles(mesh, gentle)[1], BandRole::None);
    EXPECT_THROW(true_band_roles(mesh, {}), InvalidInput);
}

TEST(Detection, PrecisionAndRecall) {
    using enum BandRole;
    const std::vector<BandRole> detected{Edge, Edge, None, Corner, Corner};
    const std::vector<BandRole> truth{Edge, None, Edge, Corner, Edge};
    const DetectionScores s = score_detection(detected, truth);
    EXPECT_EQ(s.bands.detected, 4u);
    EXPECT_EQ(s.bands.actual, 4u);
    EXPECT_EQ(s.bands.matched, 3u);
    EXPECT_DOUBLE_EQ(s.bands.precision, 0.75);
    EXPECT_DOUBLE_EQ(s.bands.recall, 0.75);
    EXPECT_DOUBLE_EQ(s.corners.precision, 0.5);
    EXPECT_DOUBLE_EQ(s.corners.recall, 1.0);
    EXPECT_THROW(score_detection(detected, std::vector<BandRole>{Edge}), InvalidInput);
}

}  // namespace
}  // namespace resharp::eval
