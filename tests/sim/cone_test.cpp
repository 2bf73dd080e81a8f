// The conical mill (V-bit, chamfer mill): its profile, and its swept volume against closed forms
// (a straight V-groove, a plunge, a ramp's flank planes) and against a dense union of copies.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <utility>

#include "mesh_checks.h"
#include "resharp/core/errors.h"
#include "resharp/sim/cone_ramp.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/simulate.h"
#include "resharp/sim/sweep.h"

namespace resharp::sim {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

TEST(ConeTool, MakeChecksItsNumbersAndGivesTheConeHeight) {
    const Tool v = Tool::make_cone(10, 90, 0, 20);
    EXPECT_EQ(v.shape, ToolShape::Cone);
    EXPECT_NEAR(v.half_angle, 45 * kDeg, 1e-15);
    EXPECT_NEAR(v.cone_height(), 5.0, 1e-12);
    EXPECT_NEAR(Tool::make_cone(12, 60, 2, 30).cone_height(), 5 / std::tan(30 * kDeg), 1e-12);
    EXPECT_EQ(Tool::make(ToolShape::FlatEnd, 6, 0, 20).cone_height(), 0.0);
    for (const double angle : {0.0, 180.0, -10.0, 200.0, std::nan("")}) {
        EXPECT_THROW(Tool::make_cone(10, angle, 0, 20), InvalidInput) << angle;
    }
    EXPECT_THROW(Tool::make_cone(-10, 90, 0, 20), InvalidInput);
    EXPECT_THROW(Tool::make_cone(10, 90, 10, 20), InvalidInput);  // tip as wide as the tool
    EXPECT_THROW(Tool::make_cone(10, 90, -1, 20), InvalidInput);
    EXPECT_THROW(Tool::make_cone(10, 90, 0, 4.9), InvalidInput);  // flutes shorter than the cone
    EXPECT_THROW(Tool::make(ToolShape::Cone, 10, 0, 20), InvalidInput);
}

TEST(ConeTool, ProfileIsTheFlatTipTheConeAndTheCylinder) {
    const Tool t = Tool::make_cone(12, 60, 2, 30);  // rt = 1, β = 30°, cone up to 4 / tan 30°
    const double c = std::cos(30 * kDeg), s = std::sin(30 * kDeg);
    const ProfilePoint tip = bottom_at(t, 0.7);
    EXPECT_EQ(tip.value, 0.0);
    EXPECT_EQ(tip.part, ToolPart::Bottom);
    const ProfilePoint flank = bottom_at(t, 3.0);
    EXPECT_NEAR(flank.value, 2.0 / std::tan(30 * kDeg), 1e-12);
    EXPECT_EQ(flank.part, ToolPart::Cone);
    EXPECT_NEAR(flank.normal_r, c, 1e-15);
    EXPECT_NEAR(flank.normal_z, -s, 1e-15);
    const ProfilePoint section = radius_at(t, 2.0);
    EXPECT_NEAR(section.value, 1.0 + 2.0 * std::tan(30 * kDeg), 1e-12);
    EXPECT_EQ(section.part, ToolPart::Cone);
    EXPECT_EQ(radius_at(t, 10.0).value, 6.0);
    EXPECT_EQ(radius_at(t, 10.0).part, ToolPart::Side);
}

ToolPath program(const std::string& text) {
    std::istringstream in(text);
    return parse_gcode(in, "cone.nc", {.start_position = Vec3(20, 15, 60)});
}

/// `stock` milled by the G-code `text` with `tool` as T1, meshed by marching cubes; checked
/// closed, manifold and outward.
OracleMesh milled(const Box3& stock, const Tool& tool, const std::string& text) {
    const OracleMesh m = mesh_dexels(simulate(stock, {{1, tool}}, program(text)).grid);
    test::expect_clean_closed_outward(m.mesh);
    return m;
}

TEST(ConeTool, StraightVGrooveHasFlanksAtTheToolAngleAndItsDepth) {
    // A 90° V-bit cuts along x at y = 15.3 with its tip 2.3 mm under the top face z = 10.
    const OracleMesh m =
        milled(Box3(Vec3(0, 0, 0), Vec3(40, 30, 10)), Tool::make_cone(10, 90, 0, 20),
               "T1 M6\nG0 X-8 Y15.3 Z30\nG0 Z7.7\nG1 X48\nG0 Z30\nM30\n");
    const double c = std::cos(45 * kDeg);
    std::size_t flank = 0;
    double deepest = 1e300;
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const Vec3& p = m.mesh.positions[v];
        if (m.surface_ids[v] % kSurfacesPerMove != static_cast<int>(ToolPart::Cone)) continue;
        deepest = std::min(deepest, p.z());
        ++flank;
        const double side = p.y() > 15.3 ? 1.0 : -1.0;
        EXPECT_NEAR(std::abs(p.y() - 15.3), p.z() - 7.7, 1e-9) << "vertex " << v;
        // The material's normal points into the groove and up, 45° from the vertical.
        EXPECT_NEAR((m.normals[v] - Vec3(0, -side * c, c)).norm(), 0.0, 1e-12) << "vertex " << v;
    }
    EXPECT_GT(flank, 500u);
    EXPECT_GE(deepest, 7.7);  // no vertex below the tip; the V's bottom is lost to the grid
    EXPECT_LT(deepest, 7.7 + 0.5);
}

TEST(ConeTool, PlungeLeavesAFrustumHole) {
    // A chamfer mill (90°, flat tip of diameter 2) plunged to z = 6.3 under the top z = 10.
    const OracleMesh m =
        milled(Box3(Vec3(0, 0, 0), Vec3(20, 20, 10)), Tool::make_cone(12, 90, 2, 20),
               "T1 M6\nG0 X10.13 Y9.71 Z30\nG1 Z6.3\nG0 Z30\nM30\n");
    std::size_t cone = 0, floor = 0;
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const Vec3& p = m.mesh.positions[v];
        const auto part = static_cast<ToolPart>(m.surface_ids[v] % kSurfacesPerMove);
        if (m.surface_ids[v] < kSurfacesPerMove) continue;  // stock faces
        const double r = std::hypot(p.x() - 10.13, p.y() - 9.71);
        if (part == ToolPart::Cone) {
            EXPECT_NEAR(r, 1.0 + (p.z() - 6.3), 1e-9) << "vertex " << v;
            ++cone;
        } else {
            EXPECT_EQ(part, ToolPart::Bottom);
            EXPECT_NEAR(p.z(), 6.3, 1e-12);
            EXPECT_LE(r, 1.0 + 1e-12);
            ++floor;
        }
    }
    EXPECT_GT(cone, 100u);
    EXPECT_GT(floor, 4u);
}

TEST(ConeTool, RampFlanksAreTheTwoTangentPlanesAlongTheMotion) {
    // A sharp 60° V-bit descends 2 mm over 10 mm along x. Its swept flanks are the planes
    // through the tip path whose normal (cos β g, -sin β) is orthogonal to the motion d.
    const Tool tool = Tool::make_cone(8, 60, 0, 20);
    const Vec3 a(2, 5, 10), b(12, 5, 8), d = b - a;
    const double beta = 30 * kDeg;
    const double gx = std::tan(beta) * d.z() / d.x();  // cos β gx dx = sin β dz
    for (const double side : {-1.0, 1.0}) {
        const Vec3 n(std::cos(beta) * gx, side * std::cos(beta) * std::sqrt(1 - gx * gx),
                     -std::sin(beta));
        ASSERT_NEAR(n.dot(d), 0.0, 1e-12);
        for (double x = 4.0; x <= 10.0; x += 0.37) {
            for (double up = 0.3; up < 3.0; up += 0.29) {
                const double z = a.z() + (x - a.x()) * d.z() / d.x() + up;
                const auto cut = cut_cone_ramp(tool, a, b, Ray{1, Vec3(x, 0, z)}, 3);
                ASSERT_TRUE(cut.has_value());
                const Crossing& c = side < 0 ? cut->enter : cut->exit;
                const Vec3 p(x, c.t, z);
                EXPECT_NEAR(n.dot(p - a), 0.0, 1e-9) << x << " " << z;
                EXPECT_NEAR((c.normal - n).norm(), 0.0, 1e-9);
                EXPECT_EQ(c.surface, tool_surface_id(3, ToolPart::Cone));
            }
        }
    }
}

/// The union of copies of the tool every `step` mm along a -> b, as one interval (the sweep is
/// convex): lies inside the sweep, and within about a step of its boundary.
struct Copies {
    std::vector<SweptVolume> copies;
    Copies(const Tool& tool, const Vec3& a, const Vec3& b, double step) {
        const int n = static_cast<int>(std::ceil((b - a).norm() / step));
        for (int i = 0; i <= n; ++i) {
            const Vec3 p = a + (static_cast<double>(i) / n) * (b - a);
            copies.emplace_back(
                tool, ToolMotion{.kind = ToolMotion::Kind::Line, .start = p, .end = p}, 0);
        }
    }
    std::optional<Interval> cut(const Ray& ray) const {
        std::optional<Interval> hull;
        std::vector<Interval> pieces;
        for (const SweptVolume& c : copies) {
            pieces.clear();
            c.intersect(ray, pieces);
            for (const Interval& i : pieces) {
                if (!hull) hull = i;
                if (i.enter.t < hull->enter.t) hull->enter = i.enter;
                if (i.exit.t > hull->exit.t) hull->exit = i.exit;
            }
        }
        return hull;
    }
};

TEST(ConeTool, RampAgreesWithADenseUnionOfCopies) {
    struct Case {
        Tool tool;
        Vec3 a, b;
    };
    const Case cases[] = {
        {Tool::make_cone(8, 60, 0, 20), Vec3(2, 5, 10), Vec3(12, 5, 8)},        // shallow V
        {Tool::make_cone(10, 90, 1.5, 8), Vec3(3, 2, 4), Vec3(9, 10, 12)},      // steep rise
        {Tool::make_cone(12, 120, 0.8, 12), Vec3(10, 10, 9), Vec3(4, 7, 6.5)},  // chamfer mill
    };
    constexpr double kStep = 0.002;
    std::mt19937 random(12);
    int index = 0;
    for (const Case& k : cases) {
        const Copies copies(k.tool, k.a, k.b, kStep);
        const SweptVolume exact(
            k.tool, ToolMotion{.kind = ToolMotion::Kind::Line, .start = k.a, .end = k.b}, 0);
        const Box3 box = exact.bounds();
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        int both = 0;
        double worst = 0.0, worst_normal = 0.0;
        for (int trial = 0; trial < 600; ++trial) {
            const int axis = trial % 3;
            Vec3 o =
                box.min() +
                (box.max() - box.min()).cwiseProduct(Vec3(u01(random), u01(random), u01(random)));
            o[axis] = 0.0;
            const Ray ray{axis, o};
            std::vector<Interval> got;
            exact.intersect(ray, got);
            const auto want = copies.cut(ray);
            ASSERT_LE(got.size(), 1u);
            if (!want) {  // between copies at most: a sliver the copies miss
                if (!got.empty()) {
                    EXPECT_LT(got[0].exit.t - got[0].enter.t, 0.2);
                }
                continue;
            }
            ASSERT_EQ(got.size(), 1u) << "trial " << trial;
            ++both;
            // The copies lie inside the sweep, and within a small multiple of the step of it.
            EXPECT_LE(got[0].enter.t, want->enter.t + 1e-9);
            EXPECT_GE(got[0].exit.t, want->exit.t - 1e-9);
            const double gap =
                std::max(want->enter.t - got[0].enter.t, got[0].exit.t - want->exit.t);
            worst = std::max(worst, gap);
            EXPECT_LT(gap, 0.02) << "trial " << trial;
            // Off the rims the normal is the tool's own, as on the copy that reaches farthest.
            for (const auto& [c, copy] :
                 {std::pair{got[0].enter, want->enter}, std::pair{got[0].exit, want->exit}}) {
                EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
                const auto part = static_cast<ToolPart>(c.surface % kSurfacesPerMove);
                if (part == ToolPart::Cone || part == ToolPart::Side) {
                    EXPECT_EQ(copy.surface % kSurfacesPerMove, c.surface % kSurfacesPerMove);
                    EXPECT_LT((c.normal - copy.normal).norm(), 0.05) << "trial " << trial;
                    worst_normal = std::max(worst_normal, (c.normal - copy.normal).norm());
                }
            }
        }
        EXPECT_GT(both, 150);
        RecordProperty("worst_gap_mm_" + std::to_string(index), test::short_number(worst));
        RecordProperty("worst_normal_" + std::to_string(index++), test::short_number(worst_normal));
    }
}

TEST(ConeTool, VRampMeshIsClosedForEveryMesher) {
    const Box3 stock(Vec3(0, 0, 0), Vec3(30, 20, 10));
    const std::map<int, Tool> tools{{1, Tool::make_cone(10, 90, 0, 20)}};
    const Simulation sim = simulate(
        stock, tools,
        program("T1 M6\nG0 X-6 Y9.7 Z30\nG0 Z9.1\nG1 X12 Z6.4\nX20 Y14.1\nG2 X26 Y8.1 I3 J-3\nG0 "
                "Z30\nM30\n"));
    for (const Mesher mesher :
         {Mesher::MarchingCubes, Mesher::Bisection, Mesher::Midpoint, Mesher::SurfaceNets}) {
        const OracleMesh m = mesh_dexels(sim.grid, {.mesher = mesher});
        test::expect_clean_closed_outward(m.mesh);
        EXPECT_EQ(m.stats.clamped_vertices, 0u) << to_string(mesher);
    }
}

}  // namespace
}  // namespace resharp::sim
