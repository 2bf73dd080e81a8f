#include "resharp/eval/ideal_points.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "oracle_square.h"
#include "resharp/eval/miss_causes.h"
#include "resharp/eval/restoration_rate.h"

namespace resharp::eval {
namespace {

using test::Square;

IdealPoint diagonal_point(const std::vector<IdealPoint>& points) {
    const auto it = std::find_if(points.begin(), points.end(), [](const IdealPoint& p) {
        return p.kind == IdealKind::Edge && std::min(p.vertices[0], p.vertices[1]) == 1 &&
               std::max(p.vertices[0], p.vertices[1]) == 2;
    });
    EXPECT_NE(it, points.end());
    return it == points.end() ? IdealPoint{} : *it;
}

// A ridge across the diagonal: the planes x - y + z = 1 (through 1) and -x + y + z = 1
// (through 2) meet on the line x = y, z = 1, which the mid-plane cuts at (0.5, 0.5, 1).
TEST(IdealPoints, RidgeAcrossTheChordIsWithinReach) {
    const Square s(Vec3(1, -1, 1), Vec3(-1, 1, 1));
    const IdealPoint p = diagonal_point(find_ideal_points(s.mesh, s.oracle));
    EXPECT_TRUE((p.position - Vec3(0.5, 0.5, 1)).norm() < 1e-12) << p.position.transpose();
    EXPECT_FALSE(p.beyond_chord);
    EXPECT_FALSE(p.on_boundary);
}

// Planes 2x + y + z = 2 (through 1) and x - 2y + 2z = -2 (through 2): both normals have a
// positive dot with 2 - 1, so eq. 5.4 fails, and the point (0.6, 1.05, -0.25), solved by hand,
// lies over neither triangle (y > 1).
TEST(IdealPoints, PlanesMeetingBesideTheEdgeAreBeyondTheChord) {
    const Square s(Vec3(2, 1, 1), Vec3(1, -2, 2));
    const IdealPoint p = diagonal_point(find_ideal_points(s.mesh, s.oracle));
    EXPECT_TRUE((p.position - Vec3(0.6, 1.05, -0.25)).norm() < 1e-12) << p.position.transpose();
    EXPECT_TRUE(p.beyond_chord);
}

TEST(IdealPoints, PointsBeyondTheChordAreScoredApart) {
    const Square s(Vec3(2, 1, 1), Vec3(1, -2, 2));
    const std::vector<IdealPoint> ideal = {diagonal_point(find_ideal_points(s.mesh, s.oracle)),
                                           {Vec3(0.5, 0.5, 0), IdealKind::Edge, 0, {0, 1}, false}};
    Mesh output = s.mesh;
    output.positions.push_back(Vec3(0.5, 0.5, 0));  // restores the second point only
    SurfaceSamples exact;
    exact.points = {Vec3(0.5, 0.5, 0)};
    exact.normals = {Vec3::UnitZ()};
    const RestorationScore r = score_restoration(s.mesh, output, ideal, exact, {.pitch = 1.0});
    EXPECT_EQ(r.beyond_chord, 1u);
    EXPECT_EQ(r.restored_beyond_chord, 0u);
    EXPECT_DOUBLE_EQ(r.rate, 0.5);
    EXPECT_DOUBLE_EQ(r.rate_within_reach, 1.0);
    const MissCauses c = find_miss_causes(s.mesh, output, ideal, r.ideal_distance, 0.05, {});
    EXPECT_EQ(c.edges[std::size_t(MissCause::BeyondChord)], 1u);
    EXPECT_EQ(c.edges[std::size_t(MissCause::NotInserted)], 0u);
}

}  // namespace
}  // namespace resharp::eval
