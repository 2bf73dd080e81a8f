#include "resharp/eval/exact_junctions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "milled_part.h"
#include "resharp/core/errors.h"

namespace resharp::eval {
namespace {

using sim::Tool;
using sim::ToolPart;
using sim::ToolShape;

const sim::Box3 kStock(Vec3(0, 0, 0), Vec3(30, 20, 10));
constexpr double kExact = 1e-8;  // mm

ExactJunctionOptions options_for(const test::MilledPart& part) {
    ExactJunctionOptions o;
    o.solver.pitch = part.options.pitch;
    return o;
}

ExactIdealPoints exact_points(const test::MilledPart& part, ExactJunctionOptions o = {}) {
    o.solver.pitch = part.options.pitch;
    const std::vector<IdealPoint> first = find_ideal_points(part.mesh(), part.oracle);
    return find_exact_ideal_points(part.mesh(), part.oracle, first, part.solid, o);
}

std::size_t count(const std::array<std::size_t, kJunctionStatusCount>& c, JunctionStatus s) {
    return c[static_cast<std::size_t>(s)];
}

double plan_distance(const Vec3& p, double x, double y) { return std::hypot(p.x() - x, p.y() - y); }

/// True when one of the vertices of `p` lies on a surface of move `move`.
bool touches_move(const test::MilledPart& part, const IdealPoint& p, std::size_t move) {
    for (int k = 0; k < (p.kind == IdealKind::Edge ? 2 : 3); ++k) {
        const std::int32_t id = part.oracle.surfaces[p.vertices[k]];
        if (id >= sim::kSurfacesPerMove && std::size_t(id / sim::kSurfacesPerMove - 1) == move) {
            return true;
        }
    }
    return false;
}

// A hole drilled 4.7 mm deep with a flat end of radius 3 (move 1): every ideal point of its
// edges lies on the circle where the wall meets the top or the floor, exactly, and nothing on
// the part is counted apart; eq. 5.2's points are off the circles (the wall curves within an
// edge).
TEST(ExactJunctions, DrilledHoleJunctionsLieOnItsCircles) {
    const test::MilledPart part(kStock, {{1, Tool::make(ToolShape::FlatEnd, 6, 0, 20)}},
                                "T1 M6\nG0 X15.23 Y10.17 Z30\nG1 Z5.3\nG0 Z30\nM30\n");
    const ExactIdealPoints ideal = exact_points(part);
    EXPECT_EQ(ideal.points.size(), count(ideal.edges, JunctionStatus::Exact) +
                                       count(ideal.corners, JunctionStatus::Exact));
    for (std::size_t s = 1; s < kJunctionStatusCount; ++s) {
        EXPECT_EQ(ideal.edges[s] + ideal.corners[s], 0u) << s;
    }
    std::size_t hole = 0;
    for (const IdealPoint& p : ideal.points) {
        if (!touches_move(part, p, 1)) continue;
        ++hole;
        EXPECT_EQ(p.kind, IdealKind::Edge);
        EXPECT_NEAR(plan_distance(p.position, 15.23, 10.17), 3.0, kExact);
        EXPECT_LE(std::min(std::abs(p.position.z() - 10), std::abs(p.position.z() - 5.3)), kExact);
    }
    EXPECT_GT(hole, 100u);  // two circles of 19 mm, about two points per grid cell
    double worst_first_order = 0.0;
    for (const IdealPoint& p : find_ideal_points(part.mesh(), part.oracle)) {
        if (!touches_move(part, p, 1)) continue;
        worst_first_order =
            std::max(worst_first_order, std::abs(plan_distance(p.position, 15.23, 10.17) - 3.0));
    }
    EXPECT_GT(worst_first_order, 1e-4);
}

// Two ball-end passes (R = 3) 2.5 mm apart, ball centres at z = 10.1: the ridge between them is
// the line y = 9.85, z = 10.1 - sqrt(9 - 1.25²). Every junction of the two passes lies on it.
// Pass one is two moves, so near x = 15 a junction of its first move's surface lies where
// the second move bounds the solid: the hand-over to that surface is what keeps it exact.
TEST(ExactJunctions, TwoBallPassesMeetOnTheirRidge) {
    const test::MilledPart part(kStock, {{1, Tool::make(ToolShape::BallEnd, 6, 0, 20)}},
                                "T1 M6\nG0 X-5 Y8.6 Z30\nG1 Z7.1\nX15.3\nX35\nG0 Z30\nX-5 "
                                "Y11.1\nG1 Z7.1\nX35\nG0 Z30\nM30\n");
    const std::int32_t pass_two = sim::tool_surface_id(7, ToolPart::Corner);
    const double ridge_z = 10.1 - std::sqrt(9 - 1.25 * 1.25);
    const auto on_ridge = [&](const ExactIdealPoints& ideal) {
        std::size_t n = 0;
        for (const IdealPoint& p : ideal.points) {
            const std::int32_t a = part.oracle.surfaces[p.vertices[0]];
            const std::int32_t b = part.oracle.surfaces[p.vertices[1]];
            const bool both_passes =
                (a == pass_two) != (b == pass_two) && std::min(a, b) >= sim::kSurfacesPerMove;
            if (p.kind != IdealKind::Edge || !both_passes) continue;
            EXPECT_NEAR(p.position.y(), 9.85, kExact) << p.position.transpose();
            EXPECT_NEAR(p.position.z(), ridge_z, kExact) << p.position.transpose();
            ++n;
        }
        return n;
    };
    const ExactIdealPoints ideal = exact_points(part);
    EXPECT_GT(on_ridge(ideal), 100u);  // about two per grid cell along 30 mm
    EXPECT_EQ(count(ideal.edges, JunctionStatus::NotBounding), 0u);

    ExactJunctionOptions no_hand_over;
    no_hand_over.max_continuations = 0;
    const ExactIdealPoints strict = exact_points(part, no_hand_over);
    EXPECT_GT(count(strict.edges, JunctionStatus::NotBounding), 0u);
    EXPECT_LT(on_ridge(strict), on_ridge(ideal));
}

// A hole plunged half outside the stock's -x face: its wall meets that face and the top (or
// the floor) at the four corners (0, 10 ± 3, 10) and (0, 10 ± 3, 5.3).
TEST(ExactJunctions, CornersWhereAWallMeetsTwoPlanes) {
    const test::MilledPart part(kStock, {{1, Tool::make(ToolShape::FlatEnd, 6, 0, 20)}},
                                "T1 M6\nG0 X0 Y10 Z30\nG1 Z5.3\nG0 Z30\nM30\n");
    const ExactIdealPoints ideal = exact_points(part);
    std::size_t corners = 0, box_corners = 0;
    for (const IdealPoint& p : ideal.points) {
        if (p.kind != IdealKind::Corner) continue;
        if (!touches_move(part, p, 1)) {
            ++box_corners;
            continue;
        }
        ++corners;
        EXPECT_NEAR(p.position.x(), 0.0, kExact);
        EXPECT_NEAR(std::abs(p.position.y() - 10), 3.0, kExact);
        EXPECT_LE(std::min(std::abs(p.position.z() - 10), std::abs(p.position.z() - 5.3)), kExact);
    }
    EXPECT_GE(corners, 2u);
    EXPECT_EQ(corners + box_corners, count(ideal.corners, JunctionStatus::Exact));
}

// A slot along x at y = 10 through the -x face, floor z = 5, walls y = 7 and 13 (move 2). A
// hand-made crossing edge from its +y wall to the -x face: above the floor the two meet on the
// line x = 0, y = 13 and both bound the solid; below it the wall is not there.
struct SlotCrossing {
    test::MilledPart part{kStock,
                          {{1, Tool::make(ToolShape::FlatEnd, 6, 0, 20)}},
                          "T1 M6\nG0 X-5 Y10 Z30\nG1 Z5\nX15\nG0 Z30\nM30\n"};
    Mesh mesh;
    Oracle oracle;
    std::vector<IdealPoint> first_order;

    explicit SlotCrossing(double z) {
        mesh = {{Vec3(0.3, 13, z + 0.3), Vec3(0, 13.3, z - 0.3), Vec3(0, 14, z + 2)}, {{0, 1, 2}}};
        oracle.normals = {-Vec3::UnitY(), -Vec3::UnitX(), -Vec3::UnitX()};
        oracle.surfaces = {sim::tool_surface_id(2, ToolPart::Side), 0, 0};
        first_order = {{Vec3(0.15, 13.15, z), IdealKind::Edge, 0, {0, 1, kNoIndex}, false}};
    }
    ExactIdealPoints exact() const {
        return find_exact_ideal_points(mesh, oracle, first_order, part.solid, options_for(part));
    }
};

TEST(ExactJunctions, JunctionWhereBothSurfacesBoundTheSolid) {
    const ExactIdealPoints above = SlotCrossing(5.9).exact();
    ASSERT_EQ(above.points.size(), 1u);
    EXPECT_LE((above.points[0].position - Vec3(0, 13, 5.9)).norm(), kExact);
}

TEST(ExactJunctions, JunctionBelowTheFloorIsCountedApart) {
    const ExactIdealPoints below = SlotCrossing(4.6).exact();
    EXPECT_TRUE(below.points.empty());
    EXPECT_EQ(count(below.edges, JunctionStatus::NotBounding), 1u);
}

TEST(ExactJunctions, RefusesAnOracleOfAnotherJob) {
    SlotCrossing s(5.9);
    s.oracle.surfaces[0] = sim::tool_surface_id(2, ToolPart::Corner);  // a flat end has none
    try {
        s.exact();
        FAIL() << "no error";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 0 lies on surface 25"), std::string::npos)
            << e.what();
    }
}

// A bull-nose ramp's surfaces are sampled by the simulator: its junctions are counted apart.
TEST(ExactJunctions, BullNoseRampJunctionsAreCountedApart) {
    const test::MilledPart part(kStock, {{1, Tool::make(ToolShape::BullNose, 8, 1.5, 20)}},
                                "T1 M6\nG0 X-6 Y10 Z30\nG1 Z8\nX36 Z6.5\nG0 Z30\nM30\n");
    const ExactIdealPoints ideal = exact_points(part);
    EXPECT_GT(count(ideal.edges, JunctionStatus::SampledSurface), 50u);
    for (const IdealPoint& p : ideal.points) {
        for (int k = 0; k < (p.kind == IdealKind::Edge ? 2 : 3); ++k) {
            EXPECT_NE(part.oracle.surfaces[p.vertices[k]] / sim::kSurfacesPerMove - 1, 2)
                << "a ramp surface in the rate";
        }
    }
}

}  // namespace
}  // namespace resharp::eval
