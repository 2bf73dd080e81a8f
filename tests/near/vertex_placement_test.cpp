// estimate_vertex_placement() on every simulator mesher (sim::mesh_dexels), on a milled job part
// and on CAD solids, aligned with the grid and at a non-zero grid phase, scaled and translated
// far, in double and through a binary STL (float32): the right placement, the pitch within 1e-6
// relative and the origin right modulo the pitch. Meshes from no grid come out Exact.

#include "resharp/near/vertex_placement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "resharp/core/errors.h"
#include "resharp/core/rounding.h"
#include "resharp/core/turn_phasor.h"
#include "resharp/io/mesh_io.h"
#include "resharp/io/stl.h"
#include "resharp/sim/csg.h"
#include "resharp/sim/csg_file.h"
#include "resharp/sim/gcode.h"
#include "resharp/sim/job.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/simulate.h"

namespace resharp {
namespace {

const std::string kSource = RESHARP_SOURCE_DIR;
const sim::Mesher kMeshers[] = {sim::Mesher::MarchingCubes, sim::Mesher::Bisection,
                                sim::Mesher::Midpoint, sim::Mesher::SurfaceNets};
const double kPhases[] = {0.0, 0.4142};  // aligned with the part, and off its round coordinates

VertexPlacement expected_placement(sim::Mesher mesher) {
    switch (mesher) {
        case sim::Mesher::Midpoint:
            return VertexPlacement::Midpoint;
        case sim::Mesher::SurfaceNets:
            return VertexPlacement::Near;
        default:
            return VertexPlacement::Exact;  // exact crossings, or bisection to h/512
    }
}

/// A mesh with the grid it was meshed on.
struct GridMesh {
    std::string name;
    Mesh mesh;
    Grid grid;
};

Grid grid_of(const sim::GridSpec& spec) { return {spec.pitch, spec.origin}; }

/// The job part milled at `pitch` and `phase`, meshed by each mesher.
std::vector<GridMesh> job_meshes(const std::string& part, double pitch, double phase) {
    const sim::Job job = sim::read_job(kSource + "/examples/" + part + "/job.json");
    const sim::ToolPath path = sim::read_gcode(job.program, {.start_position = job.start_position});
    const sim::Simulation s =
        sim::simulate(job.stock, job.tools, path, {.pitch = pitch, .grid_phase = phase});
    std::vector<GridMesh> out;
    for (sim::Mesher m : kMeshers) {
        out.push_back({part + " " + sim::to_string(m) + " phase " + std::to_string(phase),
                       sim::mesh_dexels(s.grid, {.mesher = m}).mesh, grid_of(s.grid.spec)});
    }
    return out;
}

/// The CAD solid sampled at `cells` cells along its longest side and `phase`, by each mesher.
std::vector<GridMesh> cad_meshes(const std::string& part, double cells, double phase) {
    const sim::CsgSolid solid(sim::read_csg(kSource + "/examples/cad/" + part + ".json"));
    const double pitch = sim::pitch_for_cells(solid.bounds(), cells);
    const sim::DexelGrid grid =
        sim::sample_solid(sim::phased_grid(solid.bounds(), pitch, phase), solid);
    std::vector<GridMesh> out;
    for (sim::Mesher m : kMeshers) {
        out.push_back({part + " " + sim::to_string(m) + " phase " + std::to_string(phase),
                       sim::mesh_dexels(grid, {.mesher = m}).mesh, grid_of(grid.spec)});
    }
    return out;
}

/// x -> scale * (x + shift): the mesh in other units, far from the origin.
GridMesh transformed(const GridMesh& m, double scale, const Vec3& shift) {
    GridMesh out = m;
    for (Vec3& p : out.mesh.positions) p = scale * (p + shift);
    out.grid = {scale * m.grid.pitch, scale * (m.grid.origin + shift)};
    out.name += " scaled " + std::to_string(scale) + (shift.isZero() ? "" : " translated");
    return out;
}

/// The mesh written as binary STL and read back: every coordinate rounded to float.
Mesh through_stl(const Mesh& mesh) {
    std::stringstream file;
    io::write_stl(file, mesh, io::Encoding::Binary);
    return weld(io::read_stl(file, "memory.stl"));
}

/// Checks the estimate for a mesh of `mesher`: the placement, and the grid (pitch within
/// `pitch_tolerance` relative, origin modulo the pitch within `origin_tolerance` pitches).
void expect_estimate(const GridMesh& m, sim::Mesher mesher, double pitch_tolerance,
                     double origin_tolerance) {
    SCOPED_TRACE(m.name);
    const PlacementEstimate e = estimate_vertex_placement(m.mesh);
    EXPECT_EQ(e.placement, expected_placement(mesher)) << e.reason;
    ASSERT_TRUE(e.grid.has_value()) << e.reason;
    EXPECT_NEAR(e.grid->pitch / m.grid.pitch, 1.0, pitch_tolerance) << e.reason;
    for (int a = 0; a < 3; ++a) {
        const double u = (e.grid->origin[a] - m.grid.origin[a]) / m.grid.pitch;
        EXPECT_NEAR(u - std::round(u), 0.0, origin_tolerance) << "axis " << a << ": " << e.reason;
    }
    EXPECT_FALSE(e.reason.empty());
}

/// Every mesh of `meshes` at three scales, translated far and not, in double; and through
/// float32 where the float's rounding (at most 6e-8 of the largest coordinate) is far below
/// the pitch.
void expect_estimates(const std::vector<GridMesh>& meshes) {
    const Vec3 far(1e4, -1e4, 5e3);  // mm
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const sim::Mesher mesher = kMeshers[i % std::size(kMeshers)];
        for (double scale : {1.0, 25.4, 1e-3}) {
            expect_estimate(transformed(meshes[i], scale, Vec3::Zero()), mesher, 1e-6, 1e-6);
            expect_estimate(transformed(meshes[i], scale, far), mesher, 1e-6, 1e-6);
            GridMesh rounded = transformed(meshes[i], scale, Vec3::Zero());
            rounded.mesh = through_stl(rounded.mesh);
            rounded.name += " float32";
            expect_estimate(rounded, mesher, 1e-6, 1e-4);
        }
    }
}

/// The bits of a double: +0 and -0 differ, a NaN equals itself.
std::uint64_t bits_of(double x) {
    std::uint64_t b = 0;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

TEST(RoundHalfAway, EqualsStdRoundToTheBit) {
    std::vector<double> xs = {0.0,
                              -0.0,
                              0.5,
                              -0.5,
                              1.5,
                              -1.5,
                              2.5,
                              -2.5,
                              0.49999999999999994,
                              -0.49999999999999994,
                              0.3,
                              -0.3,
                              1e15 + 0.5,
                              -1e15 - 0.5,
                              0x1p52,
                              -0x1p52,
                              0x1p52 + 1.0,
                              1e300,
                              -1e300,
                              std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::denorm_min()};
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const double scale = std::ldexp(1.0, static_cast<int>(random() % 60) - 4);
        xs.push_back(unit(random) * scale);
        xs.push_back(std::round(unit(random) * scale) + 0.5);  // exact halves
    }
    for (double x : xs) EXPECT_EQ(bits_of(round_half_away(x)), bits_of(std::round(x))) << x;
    EXPECT_TRUE(std::isnan(round_half_away(std::numeric_limits<double>::quiet_NaN())));
}

TEST(TurnPhasor, WithinItsBoundOfStdPolar) {
    // Quarter and eighth turns (the reduction's edges), small and large turns, both signs.
    std::vector<double> turns = {0.0,  -0.0, 0.125, -0.125, 0.25,   -0.25,     0.375,       0.5,
                                 -0.5, 0.75, 1.0,   -1.0,   1e-300, 1234.5678, -98765.4321, 0x1p49};
    std::mt19937_64 random(14);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        turns.push_back(unit(random) * std::ldexp(1.0, static_cast<int>(random() % 40) - 10));
    }
    double worst = 0.0;  // of the error over its bound
    for (double x : turns) {
        const std::complex<double> approximate = approximate_turn_phasor(x);
        const std::complex<double> library = std::polar(1.0, 2.0 * std::numbers::pi * x);
        const double error = std::max(std::abs(approximate.real() - library.real()),
                                      std::abs(approximate.imag() - library.imag()));
        worst = std::max(worst, error / turn_phasor_error(x));
    }
    EXPECT_LE(worst, 1.0);
    EXPECT_GT(worst, 0.0);  // it is an approximation: the bound is not vacuous
    // Beyond 2^50 turns and where not finite, the library's value itself.
    for (double x : {0x1p50, -0x1p60, std::numeric_limits<double>::infinity()}) {
        const std::complex<double> library = std::polar(1.0, 2.0 * std::numbers::pi * x);
        EXPECT_EQ(bits_of(approximate_turn_phasor(x).real()), bits_of(library.real())) << x;
    }
}

TEST(VertexPlacement, NamesRoundTrip) {
    for (VertexPlacement p :
         {VertexPlacement::Exact, VertexPlacement::Near, VertexPlacement::Midpoint}) {
        EXPECT_EQ(vertex_placement_from_string(to_string(p)), p);
    }
    EXPECT_FALSE(vertex_placement_from_string("auto").has_value());
    EXPECT_EQ(to_string(VertexPlacement::Near), "near");
}

TEST(VertexPlacement, JobPartEveryMesher) {
    for (double phase : kPhases) expect_estimates(job_meshes("mech", 1.0, phase));
}

TEST(VertexPlacement, CadSolidsEveryMesher) {
    for (const char* part : {"stepped_block", "spool", "sphere_part", "hex_prism"}) {
        for (double phase : kPhases) expect_estimates(cad_meshes(part, 60.0, phase));
    }
}

/// A sphere of radius 10 tessellated as latitude-longitude quads (48 rings of 96): vertices on
/// shared rings, but on no grid.
Mesh uv_sphere() {
    constexpr int kRings = 48, kSegments = 96;
    Mesh m;
    m.positions.push_back(Vec3(0, 0, 10));
    for (int i = 1; i < kRings; ++i) {
        const double polar = std::numbers::pi * i / kRings;
        for (int j = 0; j < kSegments; ++j) {
            const double azimuth = 2.0 * std::numbers::pi * j / kSegments;
            m.positions.push_back(10.0 * Vec3(std::sin(polar) * std::cos(azimuth),
                                              std::sin(polar) * std::sin(azimuth),
                                              std::cos(polar)));
        }
    }
    m.positions.push_back(Vec3(0, 0, -10));
    const auto ring = [](int i, int j) {
        return static_cast<Index>(1 + (i - 1) * kSegments + (j % kSegments));
    };
    const Index south = static_cast<Index>(m.positions.size() - 1);
    for (int j = 0; j < kSegments; ++j) {
        m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        for (int i = 1; i + 1 < kRings; ++i) {
            m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
        m.triangles.push_back({ring(kRings - 1, j), south, ring(kRings - 1, j + 1)});
    }
    return m;
}

/// The mesh turned 27 degrees about the axis (2, -1, 3), as bench/cad_corpus.py turns its parts.
Mesh rotated(Mesh m) {
    const Eigen::AngleAxisd turn(27.0 * std::numbers::pi / 180.0, Vec3(2, -1, 3).normalized());
    for (Vec3& p : m.positions) p = turn * p;
    return m;
}

void expect_exact_without_grid(const Mesh& mesh, const std::string& name) {
    SCOPED_TRACE(name);
    const PlacementEstimate e = estimate_vertex_placement(mesh);
    EXPECT_EQ(e.placement, VertexPlacement::Exact) << e.reason;
    EXPECT_FALSE(e.grid.has_value()) << e.reason;
    EXPECT_FALSE(e.reason.empty());
}

TEST(VertexPlacement, MeshesFromNoGridAreExact) {
    expect_exact_without_grid(uv_sphere(), "uv sphere");
    expect_exact_without_grid(through_stl(uv_sphere()), "uv sphere float32");
    const Mesh bracket = weld(io::read_mesh(kSource + "/examples/bracket.stl"));
    expect_exact_without_grid(rotated(bracket), "bracket rotated 27 degrees");
    expect_exact_without_grid(rotated(job_meshes("mech", 1.0, 0.4142)[3].mesh),
                              "surface nets rotated 27 degrees");
}

// One stray vertex (a fin off a marching-cubes mesh) moves the grid search to a grid the mesh
// looks dual to; the vertices on that grid's edges tell it from cell means.
TEST(VertexPlacement, AGridEdgeMeshWithAStrayVertexIsExact) {
    for (const double cells : {40.0, 60.0}) {
        Mesh mesh = cad_meshes("stepped_block", cells, 0.4142).front().mesh;  // mc
        const Triangle t = mesh.triangles[mesh.face_count() / 2];
        const Vec3 centre =
            (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
        mesh.positions.push_back(centre + Vec3(0.1, 0.3, 1.0));
        mesh.triangles.push_back({t[0], t[1], static_cast<Index>(mesh.vertex_count() - 1)});
        const PlacementEstimate e = estimate_vertex_placement(mesh);
        EXPECT_EQ(e.placement, VertexPlacement::Exact) << cells << ": " << e.reason;
    }
}

// CAMotics bisects to cell / 256: its vertices take the exact path.
TEST(VertexPlacement, CamoticsMeshIsExact) {
    const Mesh relief =
        weld(io::read_mesh(std::string(RESHARP_TEST_DATA_DIR) + "/relief_hang.stl"));
    const PlacementEstimate e = estimate_vertex_placement(relief);
    EXPECT_EQ(e.placement, VertexPlacement::Exact) << e.reason;
    EXPECT_FALSE(e.reason.empty());
}

TEST(VertexPlacement, GivenGridReplacesTheInferredOne) {
    const std::vector<GridMesh> meshes = cad_meshes("stepped_block", 40.0, 0.4142);
    const GridMesh& midpoint = meshes[2];
    const PlacementEstimate right = estimate_vertex_placement(midpoint.mesh, midpoint.grid);
    EXPECT_EQ(right.placement, VertexPlacement::Midpoint) << right.reason;
    ASSERT_TRUE(right.grid.has_value());
    EXPECT_EQ(right.grid->pitch, midpoint.grid.pitch);
    EXPECT_EQ(right.grid->origin, midpoint.grid.origin);
    // On a grid of another pitch no vertex lies on grid edges, nor are triangles dual: exact.
    const Grid other{0.7 * midpoint.grid.pitch, midpoint.grid.origin};
    const PlacementEstimate wrong = estimate_vertex_placement(midpoint.mesh, other);
    EXPECT_EQ(wrong.placement, VertexPlacement::Exact) << wrong.reason;
    const GridMesh& nets = meshes[3];
    EXPECT_EQ(estimate_vertex_placement(nets.mesh, nets.grid).placement, VertexPlacement::Near);
    EXPECT_THROW(estimate_vertex_placement(nets.mesh, Grid{0.0, Vec3::Zero()}), InvalidInput);
    EXPECT_THROW(estimate_vertex_placement(nets.mesh, Grid{-1.0, Vec3::Zero()}), InvalidInput);
    EXPECT_THROW(estimate_vertex_placement(nets.mesh, Grid{1.0, Vec3::Constant(NAN)}),
                 InvalidInput);
}

TEST(VertexPlacement, TooSmallMeshesAreExact) {
    const Mesh triangle{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}};
    const PlacementEstimate e = estimate_vertex_placement(triangle);
    EXPECT_EQ(e.placement, VertexPlacement::Exact);
    EXPECT_FALSE(e.grid.has_value());
    EXPECT_EQ(estimate_vertex_placement(Mesh{}).placement, VertexPlacement::Exact);
}

}  // namespace
}  // namespace resharp
