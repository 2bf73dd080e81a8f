#include "resharp/eval/exact_surface.h"

#include <gtest/gtest.h>

#include <random>

#include "milled_part.h"

namespace resharp::eval {
namespace {

using sim::Tool;
using sim::ToolShape;
using Kind = MachinedSolid::SurfaceKind;

const sim::Box3 kStock(Vec3(0, 0, 0), Vec3(40, 30, 20));

/// Every vertex of the milled part lies on its surface's reconstruction, whose gradient is the
/// oracle's normal there (up to sign: tool surfaces' values grow away from the tool).
void expect_vertices_on_their_surfaces(const test::MilledPart& part) {
    std::size_t checked = 0;
    for (std::size_t v = 0; v < part.mesh().vertex_count(); ++v) {
        const Vec3& p = part.mesh().positions[v];
        const MachinedSolid::SurfaceNear s = part.solid.surface_near(part.oracle.surfaces[v], p);
        ASSERT_EQ(s.kind, Kind::Exact) << "vertex " << v << " surface " << part.oracle.surfaces[v];
        EXPECT_LE(s.distance, 1e-9) << "vertex " << v << " surface " << part.oracle.surfaces[v];
        const Vec3 g = s.surface->evaluate(p).gradient.normalized();
        EXPECT_GE(std::abs(g.dot(part.oracle.normals[v])), 1.0 - 1e-9)
            << "vertex " << v << " surface " << part.oracle.surfaces[v];
        ++checked;
    }
    EXPECT_GT(checked, 1000u);
}

// Lines, arcs, plunges and ramps with each exact tool: stock faces, bottoms, sides, tops, the
// ball's capsules, the torus of a bull-nose's horizontal pass, the rims' slanted cylinders.
TEST(ExactSurface, FlatEndVerticesLieOnTheirSurfaces) {
    const test::MilledPart part(
        kStock, {{1, Tool::make(ToolShape::FlatEnd, 8, 0, 12)}},
        "T1 M6\nG0 X-6 Y8 Z30\nG1 Z16.3\nX20\nG2 X30 Y18 I0 J10\nG1 X34 Y24 Z12.1\n"
        "G0 Z30\nG0 X10 Y22\nG1 Z5.7\nG0 Z30\nM30\n");
    expect_vertices_on_their_surfaces(part);
}

TEST(ExactSurface, BallEndVerticesLieOnTheirSurfaces) {
    const test::MilledPart part(
        kStock, {{1, Tool::make(ToolShape::BallEnd, 6, 0, 10)}},
        "T1 M6\nG0 X-5 Y7 Z30\nG1 Z15.2\nX18 Z13.9\nG3 X28 Y17 I0 J10\nG1 X12 Y23.3\n"
        "G0 Z30\nG0 X33 Y6\nG1 Z12.6\nG0 Z30\nM30\n");
    expect_vertices_on_their_surfaces(part);
}

TEST(ExactSurface, HelixAndBullNosePassVerticesLieOnTheirSurfaces) {
    const test::MilledPart part(kStock,
                                {{1, Tool::make(ToolShape::FlatEnd, 6, 0, 12)},
                                 {2, Tool::make(ToolShape::BullNose, 8, 1.5, 12)}},
                                "T1 M6\nG0 X14 Y15 Z30\nG1 Z21\nG2 X14 Y15 Z14.4 I6 J0\nG0 Z30\n"
                                "T2 M6\nG0 X-6 Y24 Z30\nG1 Z17.2\nX46\nG0 Z30\nM30\n");
    expect_vertices_on_their_surfaces(part);
}

// The simulator samples a bull-nose ramp: its surfaces are not claimed exact; ids no move makes
// are unknown.
TEST(ExactSurface, BullNoseRampIsSampledAndStrayIdsUnknown) {
    const test::MilledPart part(kStock, {{1, Tool::make(ToolShape::BullNose, 8, 1.5, 12)}},
                                "T1 M6\nG0 X-6 Y15 Z30\nG1 Z18\nX46 Z15\nG0 Z30\nM30\n");
    const std::int32_t ramp = sim::tool_surface_id(2, sim::ToolPart::Corner);
    std::size_t sampled = 0;
    for (std::size_t v = 0; v < part.mesh().vertex_count(); ++v) {
        if (part.oracle.surfaces[v] != ramp) continue;
        EXPECT_EQ(part.solid.surface_near(ramp, part.mesh().positions[v]).kind, Kind::Sampled);
        ++sampled;
    }
    EXPECT_GT(sampled, 100u);
    EXPECT_EQ(part.solid.surface_near(7, Vec3(1, 1, 1)).kind, Kind::Unknown);
    EXPECT_EQ(
        part.solid.surface_near(sim::tool_surface_id(99, sim::ToolPart::Side), Vec3::Ones()).kind,
        Kind::Unknown);
}

// Each form's gradient against central differences of its value, at random points.
TEST(ExactSurface, GradientsMatchTheValues) {
    sim::ToolMotion line{.start = Vec3(1, 2, 3), .end = Vec3(6, 4, 1)};
    sim::ToolMotion arc{.kind = sim::ToolMotion::Kind::Arc,
                        .start = Vec3(5, 0, 2),
                        .end = Vec3(0, 5, 2),
                        .center = Eigen::Vector2d(0, 0),
                        .radius = 5,
                        .start_angle = 0,
                        .sweep = 1.5707963267948966};
    std::vector<ImplicitSurface> forms;
    forms.push_back(
        {.form = ImplicitSurface::Form::Plane, .normal = Vec3(0, 0.6, 0.8), .offset = 2});
    forms.push_back({.form = ImplicitSurface::Form::Wall, .motion = line, .radius = 2});
    forms.push_back({.form = ImplicitSurface::Form::Wall, .motion = arc, .radius = 2});
    forms.push_back({.form = ImplicitSurface::Form::Toroidal,
                     .motion = arc,
                     .radius = 1.5,
                     .inset = 2.5,
                     .height = 3.5});
    forms.push_back({.form = ImplicitSurface::Form::Capsule, .motion = line, .radius = 3});
    forms.push_back(
        {.form = ImplicitSurface::Form::Rim, .motion = line, .radius = 4, .height = 0.5});
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-8.0, 8.0);
    const double step = 1e-6;
    for (std::size_t i = 0; i < forms.size(); ++i) {
        for (int k = 0; k < 200; ++k) {
            const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
            const SurfaceValue f = forms[i].evaluate(p);
            for (int axis = 0; axis < 3; ++axis) {
                const Vec3 d = step * Vec3::Unit(axis);
                const double numeric =
                    (forms[i].evaluate(p + d).value - forms[i].evaluate(p - d).value) / (2 * step);
                EXPECT_NEAR(f.gradient[axis], numeric, 1e-5) << "form " << i << " axis " << axis;
            }
        }
    }
}

}  // namespace
}  // namespace resharp::eval
