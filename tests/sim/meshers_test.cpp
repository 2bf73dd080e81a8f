// The four meshers of mesh_dexels() on shapes with a known exact surface: each mesh closed,
// manifold and outward, each vertex within its mesher's distance of the surface, and the oracle's
// nearest surface point within the bound docs/oracle.md gives.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>
#include <sstream>

#include "mesh_checks.h"
#include "resharp/core/errors.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/diagnostics.h"
#include "resharp/sim/gcode.h"
#include "resharp/sim/job.h"
#include "resharp/sim/marching_cubes.h"
#include "resharp/sim/simulate.h"
#include "resharp/sim/solids.h"

namespace resharp::sim {
namespace {

constexpr double kPitch = 0.5;
const Mesher kMeshers[] = {Mesher::MarchingCubes, Mesher::Bisection, Mesher::Midpoint,
                           Mesher::SurfaceNets};

/// How far from the exact surface each mesher may put a vertex (header of marching_cubes.h).
double vertex_bound(Mesher mesher) {
    switch (mesher) {
        case Mesher::MarchingCubes:
            return 1e-12;
        case Mesher::Bisection:
            return kPitch / 512 + 1e-12;
        case Mesher::Midpoint:
            return kPitch / 2;
        case Mesher::SurfaceNets:
            return std::sqrt(3.0) * kPitch;  // the mean of crossings on its cell's edges
    }
    return 0.0;
}

/// A solid sampled on the grid, with its exact nearest-point function.
struct KnownSolid {
    DexelGrid grid;
    std::function<Vec3(const Vec3&)> nearest;  ///< the exact surface point nearest p
};

const Box3 kBox(Vec3(0.37, 0.29, 0.41), Vec3(8.21, 7.13, 6.07));
const Vec3 kCentre(0.13, -0.21, 0.37);
constexpr double kRadius = 4.3;

KnownSolid box_solid() {
    KnownSolid s{sample_solid(grid_enclosing(kBox, kPitch), axis_box(kBox, 0)), nullptr};
    s.nearest = [](const Vec3& p) {
        Vec3 q = p.cwiseMax(kBox.min()).cwiseMin(kBox.max());
        if (q != p) return q;  // outside: the nearest point of the box
        int axis = 0;
        double gap = std::numeric_limits<double>::infinity(), plane = 0.0;
        for (int a = 0; a < 3; ++a) {
            for (const double at : {kBox.min()[a], kBox.max()[a]}) {
                if (std::abs(p[a] - at) < gap) gap = std::abs(p[a] - at), axis = a, plane = at;
            }
        }
        q[axis] = plane;
        return q;
    };
    return s;
}

KnownSolid sphere_solid() {
    const Sphere ball(kCentre, kRadius, 7);
    KnownSolid s{sample_solid(grid_enclosing(ball.bounds(), kPitch), ball), nullptr};
    s.nearest = [](const Vec3& p) -> Vec3 {
        return kCentre + kRadius * (p - kCentre).normalized();
    };
    return s;
}

std::string name_of(Mesher m) { return to_string(m); }

class Meshers : public ::testing::TestWithParam<Mesher> {};

TEST_P(Meshers, BoxAndSphereAreClosedManifoldOutwardWithVerticesNearTheSurface) {
    const std::pair<const char*, KnownSolid> solids[] = {{"box", box_solid()},
                                                         {"sphere", sphere_solid()}};
    for (const auto& [name, solid] : solids) {
        const OracleMesh m = mesh_dexels(solid.grid, {.mesher = GetParam()});
        test::expect_clean_closed_outward(m.mesh);
        ASSERT_EQ(m.surface_points.size(), m.mesh.vertex_count());
        double farthest = 0.0;
        for (const Vec3& p : m.mesh.positions) {
            farthest = std::max(farthest, (p - solid.nearest(p)).norm());
        }
        EXPECT_LE(farthest, vertex_bound(GetParam()));
        RecordProperty(std::string("farthest_vertex_mm_") + name, test::short_number(farthest));
    }
}

TEST_P(Meshers, SurfacePointsOnASphereAreWithinTheBound) {
    // The foot on the tangent plane at a crossing x seen at angle theta from the vertex's own
    // direction lies rho (1 - cos theta) + |delta| sin theta from the nearest point, delta the
    // vertex's distance from the sphere, sin theta = |foot - x| / (rho + delta) and
    // |foot - x| <= |p - x| <= the vertex bound (docs/oracle.md).
    const KnownSolid solid = sphere_solid();
    const OracleMesh m = mesh_dexels(solid.grid, {.mesher = GetParam()});
    double worst = 0.0, worst_normal = 0.0;
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const Vec3& p = m.mesh.positions[v];
        const Vec3 exact = solid.nearest(p);
        const double delta = (p - exact).norm();
        const double sine = vertex_bound(GetParam()) / (kRadius - delta);
        const double bound = kRadius * (1 - std::sqrt(1 - sine * sine)) + delta * sine;
        const double error = (m.surface_points[v] - exact).norm();
        EXPECT_LE(error, bound + 1e-12) << "vertex " << v;
        EXPECT_EQ(m.surface_ids[v], 7);
        worst = std::max(worst, error);
        worst_normal = std::max(worst_normal, (m.normals[v] - (exact - kCentre) / kRadius).norm());
    }
    RecordProperty("worst_surface_point_error_mm", test::short_number(worst));
    RecordProperty("worst_normal_error", test::short_number(worst_normal));
    if (GetParam() == Mesher::MarchingCubes) {
        EXPECT_LE(worst, 1e-12);
    }
}

TEST_P(Meshers, SurfacePointsOnABoxAreExactOffItsEdges) {
    // On a plane the foot is exact; a vertex whose nearest point is on a sharp edge may get the
    // foot on one face's plane beyond the edge, within 2 |p - x| of the true point.
    const KnownSolid solid = box_solid();
    const OracleMesh m = mesh_dexels(solid.grid, {.mesher = GetParam()});
    std::size_t off = 0;
    double worst = 0.0;
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const Vec3& p = m.mesh.positions[v];
        const Vec3 exact = solid.nearest(p);
        const double error = (m.surface_points[v] - exact).norm();
        EXPECT_LE(error, 2 * ((p - exact).norm() + vertex_bound(GetParam())) + 1e-12);
        worst = std::max(worst, error);
        // Candidate crossings lie on the edges of the vertex's cells, within sqrt(3) h of it:
        // farther than that from a second face, the point must be exact.
        const double reach = std::sqrt(3.0) * kPitch + vertex_bound(GetParam());
        int near_faces = 0;
        for (int a = 0; a < 3; ++a) {
            near_faces += std::min(std::abs(exact[a] - kBox.min()[a]),
                                   std::abs(exact[a] - kBox.max()[a])) < reach;
        }
        if (near_faces == 1) {
            EXPECT_LE(error, 1e-12) << "vertex " << v;
        } else {
            off += error > 1e-12;
        }
    }
    RecordProperty("vertices_off_near_edges", std::to_string(off));
    RecordProperty("worst_surface_point_error_mm", test::short_number(worst));
}

/// A ball end mill of radius 2.5 plunged from above to a tip height of 5.63 into the stock
/// [0, 12] x [0, 11] x [0, 9.2]: a hole with a hemispherical floor centred at (6.07, 5.33).
Simulation ball_plunge() {
    const std::map<int, Tool> tools{{1, Tool::make(ToolShape::BallEnd, 5, 0, 20)}};
    std::istringstream in("T1 M6\nG0 X6.07 Y5.33 Z20\nG1 Z5.63\nG0 Z20\nM30\n");
    const ToolPath path = parse_gcode(in, "plunge.nc", {.start_position = Vec3(6, 5, 30)});
    return simulate(Box3(Vec3(0, 0, 0), Vec3(12, 11, 9.2)), tools, path);
}

TEST_P(Meshers, BallEndPlungeIsClosedWithItsFloorVerticesNearTheSphere) {
    const OracleMesh m = mesh_dexels(ball_plunge().grid, {.mesher = GetParam()});
    test::expect_clean_closed_outward(m.mesh);
    const Vec3 centre(6.07, 5.33, 5.63 + 2.5);
    std::size_t checked = 0;
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        const Vec3& p = m.mesh.positions[v];
        // Below the centre the nearest surface is the hemisphere.
        if (p.z() > centre.z() - 0.3) continue;
        if ((p - centre).norm() > 4.0) continue;  // the stock's bottom face, far below
        EXPECT_NEAR((p - centre).norm(), 2.5, vertex_bound(GetParam())) << "vertex " << v;
        ++checked;
    }
    EXPECT_GT(checked, 50u);
}

OracleMesh mesh_example(const std::string& name, Mesher mesher) {
    const Job job = read_job(std::string(RESHARP_SOURCE_DIR) + "/examples/" + name + "/job.json");
    const Simulation sim = simulate(job.stock, job.tools,
                                    read_gcode(job.program, {.start_position = job.start_position}),
                                    {.pitch = job.pitch});
    return mesh_dexels(sim.grid, {.mesher = mesher});
}

TEST_P(Meshers, BracketAndVCarveExamplesAreClosedManifoldOutward) {
    for (const char* example : {"bracket", "vcarve"}) {
        const OracleMesh m = mesh_example(example, GetParam());
        test::expect_clean_closed_outward(m.mesh);
        EXPECT_EQ(m.stats.clamped_vertices, 0u) << example;
        double farthest = 0.0;
        for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
            farthest = std::max(farthest, (m.mesh.positions[v] - m.surface_points[v]).norm());
            EXPECT_NEAR(m.normals[v].norm(), 1.0, 1e-12);
        }
        EXPECT_LE(farthest, vertex_bound(GetParam())) << example;
    }
}

TEST(Meshers, VCarveFlanksAreConeFacesAtTheirBitAngles) {
    // Every cone vertex of the example's 90° tools has its normal 45° from the vertical, of
    // the 60° bit (tool 2, moves between its change and the next) 60°.
    const OracleMesh m = mesh_example("vcarve", Mesher::MarchingCubes);
    std::size_t cone = 0, steep = 0;
    for (std::size_t v = 0; v < m.mesh.vertex_count(); ++v) {
        if (m.surface_ids[v] % kSurfacesPerMove != static_cast<int>(ToolPart::Cone)) continue;
        ++cone;
        const double from_vertical = std::acos(std::clamp(m.normals[v].z(), -1.0, 1.0));
        const bool is_45 = std::abs(from_vertical - std::numbers::pi / 4) < 1e-9;
        const bool is_60 = std::abs(from_vertical - std::numbers::pi / 3) < 1e-9;
        EXPECT_TRUE(is_45 || is_60) << "vertex " << v << " at " << from_vertical;
        steep += is_60;
    }
    EXPECT_GT(cone, 10000u);
    EXPECT_GT(steep, 500u);
}

TEST_P(Meshers, SeamDuplicatesAddExactlyTheTrianglesOnTheirPlanes) {
    const KnownSolid solid = sphere_solid();
    const OracleMesh plain = mesh_dexels(solid.grid, {.mesher = GetParam()});
    const OracleMesh seamed = mesh_dexels(solid.grid, {.mesher = GetParam(), .seam_duplicates = 3});
    ASSERT_EQ(seamed.mesh.positions, plain.mesh.positions);
    const std::size_t n = plain.mesh.face_count();
    ASSERT_GT(seamed.mesh.face_count(), n);
    EXPECT_EQ(seamed.stats.duplicated_triangles, seamed.mesh.face_count() - n);
    EXPECT_TRUE(std::equal(plain.mesh.triangles.begin(), plain.mesh.triangles.end(),
                           seamed.mesh.triangles.begin()));
    // The seams are the node planes x_p, p = 1..3, at node index floor(p (nx - 1) / 4)
    // (docs/oracle.md): exactly the triangles touching or crossing one are appended, in order.
    const GridSpec& spec = solid.grid.spec;
    std::vector<double> planes;
    for (int p = 1; p <= 3; ++p) planes.push_back(spec.node(0, p * (spec.counts[0] - 1) / 4));
    std::vector<Triangle> expected;
    for (const Triangle& t : plain.mesh.triangles) {
        double lo = 1e300, hi = -1e300;
        for (const Index v : t) {
            lo = std::min(lo, plain.mesh.positions[v].x());
            hi = std::max(hi, plain.mesh.positions[v].x());
        }
        if (std::any_of(planes.begin(), planes.end(),
                        [&](double x) { return lo <= x && x <= hi; })) {
            expected.push_back(t);
        }
    }
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), seamed.mesh.triangles.begin() + n,
                           seamed.mesh.triangles.end()));
    const MeshDiagnostics d = diagnose(seamed.mesh, build_connectivity(seamed.mesh));
    EXPECT_EQ(d.duplicate_faces, seamed.stats.duplicated_triangles);
    EXPECT_THROW(mesh_dexels(solid.grid, {.mesher = GetParam(), .seam_duplicates = 1000}),
                 InvalidInput);
}

INSTANTIATE_TEST_SUITE_P(AllMeshers, Meshers, ::testing::ValuesIn(kMeshers),
                         [](const auto& param_info) {
                             std::string name = name_of(param_info.param);
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(Meshers, MidpointAndBisectionKeepTheTopologyOfMarchingCubes) {
    const KnownSolid solid = sphere_solid();
    const OracleMesh mc = mesh_dexels(solid.grid);
    for (const Mesher m : {Mesher::Bisection, Mesher::Midpoint}) {
        const OracleMesh other = mesh_dexels(solid.grid, {.mesher = m});
        EXPECT_EQ(other.mesh.vertex_count(), mc.mesh.vertex_count());
        // Each vertex stays on its own cell edge: it differs from the crossing in one coordinate.
        for (std::size_t v = 0; v < mc.mesh.vertex_count(); ++v) {
            const Vec3 d = other.mesh.positions[v] - mc.mesh.positions[v];
            EXPECT_LE((d.array() != 0.0).count(), 1) << to_string(m) << " vertex " << v;
            EXPECT_LE(d.norm(), m == Mesher::Midpoint ? kPitch / 2 : kPitch / 512);
        }
    }
    // Midpoints lie halfway between grid nodes.
    const OracleMesh mid = mesh_dexels(solid.grid, {.mesher = Mesher::Midpoint});
    const Vec3 origin = solid.grid.spec.origin;
    for (const Vec3& p : mid.mesh.positions) {
        const Vec3 cells = (p - origin) / kPitch;
        int halves = 0;
        for (int a = 0; a < 3; ++a)
            halves += std::abs(cells[a] - std::floor(cells[a]) - 0.5) < 1e-9;
        EXPECT_EQ(halves, 1);
    }
}

TEST(Meshers, SurfaceNetsPutOneVertexPerCellPolygonAndTwoTrianglesPerCrossedEdge) {
    const KnownSolid solid = sphere_solid();
    const OracleMesh mc = mesh_dexels(solid.grid);
    const OracleMesh net = mesh_dexels(solid.grid, {.mesher = Mesher::SurfaceNets});
    EXPECT_EQ(net.mesh.face_count(), 2 * mc.mesh.vertex_count());
    // A sphere is a closed genus-0 surface: V - E + F = 2 with E = 3F / 2.
    EXPECT_EQ(net.mesh.vertex_count(), net.mesh.face_count() / 2 + 2);
    // Each vertex lies in a cell the surface crosses: one around a crossed edge, an edge
    // holding a marching-cubes vertex.
    const GridSpec& spec = solid.grid.spec;
    const auto cell_of = [&](const Vec3& p) {
        std::array<long, 3> c{};
        for (int a = 0; a < 3; ++a)
            c[a] = std::lround(std::floor((p[a] - spec.origin[a]) / kPitch));
        return c;
    };
    std::set<std::array<long, 3>> crossed;
    for (const Vec3& q : mc.mesh.positions) {
        std::array<long, 3> c = cell_of(q);
        int along = -1;  // the one axis whose coordinate is off the grid
        for (int a = 0; a < 3; ++a) {
            const long k = std::lround((q[a] - spec.origin[a]) / kPitch);
            if (q[a] == spec.node(a, static_cast<int>(k))) {
                c[a] = k;
            } else {
                EXPECT_EQ(along, -1);
                along = a;
            }
        }
        ASSERT_NE(along, -1);
        for (int q2 = 0; q2 < 4; ++q2) {
            std::array<long, 3> around = c;
            around[(along + 1) % 3] -= q2 & 1;
            around[(along + 2) % 3] -= q2 >> 1;
            crossed.insert(around);
        }
    }
    for (std::size_t v = 0; v < net.mesh.vertex_count(); ++v) {
        EXPECT_TRUE(crossed.count(cell_of(net.mesh.positions[v]))) << "vertex " << v;
    }
    // Each quad is its two triangles in a row, split along its shorter diagonal.
    const auto& p = net.mesh.positions;
    for (std::size_t f = 0; f + 1 < net.mesh.face_count(); f += 2) {
        const Triangle& a = net.mesh.triangles[f];
        const Triangle& b = net.mesh.triangles[f + 1];
        EXPECT_EQ(a[0], b[0]);
        EXPECT_EQ(a[2], b[1]);
        EXPECT_LE((p[a[0]] - p[a[2]]).norm(), (p[a[1]] - p[b[2]]).norm()) << "quad " << f / 2;
    }
}

TEST(Meshers, NamesRoundTripAndUnknownNamesAreRefused) {
    for (const Mesher m : kMeshers) EXPECT_EQ(mesher_from_string(to_string(m)), m);
    EXPECT_FALSE(mesher_from_string("marching-cubes").has_value());
    EXPECT_FALSE(mesher_from_string("").has_value());
    EXPECT_THROW(mesh_dexels(sphere_solid().grid, {.bisection_steps = 0}), InvalidInput);
}

}  // namespace
}  // namespace resharp::sim
