#include "resharp/sim/simulate.h"

#include <gtest/gtest.h>

#include <sstream>

#include "mesh_checks.h"
#include "resharp/core/errors.h"
#include "resharp/sim/marching_cubes.h"

namespace resharp::sim {
namespace {

const Box3 kStock(Vec3(0, 0, 0), Vec3(40, 30, 20));

ToolPath program(const std::string& text) {
    std::istringstream in(text);
    return parse_gcode(in, "test.nc", {.start_position = Vec3(20, 15, 60)});
}

/// Distance from p to the exact surface `id` of a stock milled by one straight or plunging
/// flat-end move of radius R from a to b, and that surface's outward normal.
struct ExactFace {
    double distance;
    Vec3 normal;
};

ExactFace exact_face(const Vec3& p, std::int32_t id, const Vec3& a, const Vec3& b, double radius) {
    if (id < 6) {  // stock face
        const int axis = id / 2;
        const bool is_max = id % 2 == 1;
        return {std::abs(p[axis] - (is_max ? kStock.max() : kStock.min())[axis]),
                (is_max ? 1.0 : -1.0) * Vec3::Unit(axis)};
    }
    const auto part = static_cast<ToolPart>(id % kSurfacesPerMove);
    if (part == ToolPart::Bottom) return {std::abs(p.z() - std::min(a.z(), b.z())), Vec3::UnitZ()};
    EXPECT_EQ(part, ToolPart::Side);
    const Eigen::Vector2d d = (b - a).head<2>();
    const double s = d.squaredNorm() > 0
                         ? std::clamp((p - a).head<2>().dot(d) / d.squaredNorm(), 0.0, 1.0)
                         : 0.0;
    const Eigen::Vector2d radial = p.head<2>() - (a.head<2>() + s * d);
    return {std::abs(radial.norm() - radius), -Vec3(radial.x(), radial.y(), 0).normalized()};
}

void expect_exact_oracle(const OracleMesh& m, const Vec3& a, const Vec3& b, double radius) {
    const double tolerance = 1e-9 * kStock.sizes().maxCoeff();
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const ExactFace face = exact_face(m.mesh.positions[v], m.surface_ids[v], a, b, radius);
        EXPECT_LE(face.distance, tolerance) << "vertex " << v << " surface " << m.surface_ids[v];
        EXPECT_LE((m.normals[v] - face.normal).norm(), 1e-9) << "vertex " << v;
    }
}

TEST(Simulate, StraightSlotIsClosedManifoldWithExactVertices) {
    const std::map<int, Tool> tools{{1, Tool::make(ToolShape::FlatEnd, 8, 0, 30)}};
    const ToolPath path = program("T1 M6\nG0 X-10 Y14.3 Z40\nG0 Z12.7\nG1 X50\nG0 Z40\nM30\n");
    const Simulation sim = simulate(kStock, tools, path);
    EXPECT_EQ(sim.stats.cutting_moves, 1u);  // the rapids stay clear of the stock
    const OracleMesh m = mesh_dexels(sim.grid);
    test::expect_clean_closed_outward(m.mesh);
    expect_exact_oracle(m, Vec3(-10, 14.3, 12.7), Vec3(50, 14.3, 12.7), 4.0);
    std::set<int> parts;
    for (auto id : m.surface_ids) parts.insert(id < 6 ? -1 : id % kSurfacesPerMove);
    EXPECT_TRUE(parts.count(static_cast<int>(ToolPart::Bottom)));
    EXPECT_TRUE(parts.count(static_cast<int>(ToolPart::Side)));
}

TEST(Simulate, DrilledHoleIsClosedManifoldWithExactVertices) {
    const std::map<int, Tool> tools{{2, Tool::make(ToolShape::FlatEnd, 5, 0, 30)}};
    const ToolPath path = program("T2 M6\nG0 X17.3 Y13.9 Z30\nG1 Z8.3\nG0 Z30\n");
    const OracleMesh m = mesh_dexels(simulate(kStock, tools, path).grid);
    test::expect_clean_closed_outward(m.mesh);
    expect_exact_oracle(m, Vec3(17.3, 13.9, 30), Vec3(17.3, 13.9, 8.3), 2.5);
}

TEST(Simulate, ThroughHoleWithFacesOnGridPlanesStaysClosed) {
    const std::map<int, Tool> tools{{1, Tool::make(ToolShape::FlatEnd, 6, 0, 40)}};
    const ToolPath path = program("T1 M6\nG0 X20 Y15 Z30\nG1 Z-5\nG1 X30\nG0 Z30\n");
    const OracleMesh m = mesh_dexels(
        simulate(kStock, tools, path,
                 {.pitch = 0.5, .grid_phase = 0.0, .helix_tolerance = 1e-3, .sweep = {}})
            .grid);
    const MeshDiagnostics d = diagnose(m.mesh, build_connectivity(m.mesh));
    EXPECT_EQ(d.boundary_edges + d.nonmanifold_edges + d.inconsistent_edges, 0u);
    EXPECT_EQ(m.stats.clamped_vertices, 0u);
}

TEST(Simulate, BallEndArcsAndHelixGiveAClosedMesh) {
    const std::map<int, Tool> tools{{1, Tool::make(ToolShape::BallEnd, 6, 0, 30)},
                                    {2, Tool::make(ToolShape::BullNose, 8, 1, 30)}};
    const ToolPath path = program(
        "T1 M6\nG0 X10 Y15 Z25\nG1 Z17\nG3 X30 Y15 I10 J0\nG2 X10 Y15 Z15 R10\n"
        "T2 M6\nG0 X25 Y8 Z25\nG1 Z18\nG1 X35 Y22 Z16\nG0 Z30\n");
    const Simulation sim = simulate(kStock, tools, path);
    EXPECT_GT(sim.stats.swept_volumes, sim.stats.cutting_moves);  // the helix became ramps
    const OracleMesh m = mesh_dexels(sim.grid);
    test::expect_clean_closed_outward(m.mesh);
    for (const Vec3& n : m.normals) EXPECT_NEAR(n.norm(), 1.0, 1e-9);
}

TEST(Simulate, RejectsToolsMissingFromTheTable) {
    const ToolPath path = program("T7 M6\nG1 X1\n");
    try {
        simulate(kStock, {}, path);
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("test.nc: line 2: uses tool T7"), std::string::npos);
    }
}

}  // namespace
}  // namespace resharp::sim
