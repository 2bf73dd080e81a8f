#include "resharp/mesh/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "resharp/core/errors.h"
#include "resharp/mesh/geometry.h"
#include "support/simple_meshes.h"

namespace resharp {
namespace {

TEST(Weld, MergesExactlyEqualPointsOfAnStlSoup) {
    const TriangleSoup soup = test::box_soup();
    ASSERT_EQ(soup.points.size(), 36u);
    const Mesh mesh = weld(soup);
    EXPECT_EQ(mesh.vertex_count(), 8u);
    EXPECT_EQ(mesh.face_count(), 12u);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(mesh.positions[mesh.triangles[f][k]], soup.points[soup.triangles[f][k]]);
        }
    }
}

TEST(Weld, KeepsPointsThatDifferInTheLastBit) {
    TriangleSoup soup;
    const double x = 1.0;
    soup.points = {{0, 0, 0}, {x, 0, 0}, {0, 1, 0}, {std::nextafter(x, 2.0), 0, 0},
                   {0, 0, 0}, {0, 1, 0}};
    soup.triangles = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_EQ(weld(soup).vertex_count(), 4u);
}

TEST(Weld, FoldsNegativeZeroIntoZero) {
    TriangleSoup soup;
    soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0, -0.0, 0}};
    soup.triangles = {{0, 1, 2}, {3, 2, 1}};
    EXPECT_EQ(weld(soup).vertex_count(), 3u);
}

TEST(Weld, DropsUnusedPoints) {
    TriangleSoup soup;
    soup.points = {{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    soup.triangles = {{1, 2, 3}};
    const Mesh mesh = weld(soup);
    EXPECT_EQ(mesh.vertex_count(), 3u);
    EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
}

TEST(Weld, LeavesNoSpareCapacityInThePositions) {
    // The positions stay through a whole restoration: spare capacity is memory held for
    // nothing. A closed box (as many vertices as reserved), a strip of open triangles (more
    // than reserved) and a soup with unused points (fewer).
    TriangleSoup strip;
    for (int i = 0; i < 40; ++i) {
        const Index p = static_cast<Index>(strip.points.size());
        strip.points.insert(strip.points.end(), {{double(i), 0, 0}, {i + 1.0, 0, 0}, {0, 1, 0}});
        strip.triangles.push_back({p, p + 1, p + 2});
    }
    TriangleSoup unused = test::box_soup();
    unused.points.resize(unused.points.size() + 50, Vec3(9, 9, 9));
    for (const TriangleSoup& soup : {test::box_soup(), strip, unused}) {
        const Mesh mesh = weld(soup);
        EXPECT_EQ(mesh.positions.capacity(), mesh.positions.size());
    }
    EXPECT_EQ(weld(strip).vertex_count(), 42u);
}

TEST(Weld, MapsEachSoupPointToItsVertex) {
    TriangleSoup soup;
    soup.points = {{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
    soup.triangles = {{1, 2, 3}, {4, 5, 3}};
    const WeldedMesh welded = weld_mapped(soup);
    EXPECT_EQ(welded.vertex_of_point, (std::vector<Index>{kNoIndex, 0, 1, 2, 1, 3}));
    EXPECT_EQ(welded.mesh.triangles, weld(soup).triangles);
}

TEST(Weld, KeepsEveryPointOfManyLooseTrianglesAndFindsTheirCopies) {
    // Three distinct points per triangle: six times the vertices a closed mesh of as many faces
    // has, so the position table must grow several times. Then the same soup again: all copies.
    TriangleSoup soup;
    const Index loose = 5000;
    for (Index f = 0; f < 2 * loose; ++f) {
        const double x = f % loose;
        soup.points.insert(soup.points.end(), {{x, 0, 0}, {x, 1, 0.5}, {x + 0.5, 0, 1}});
        soup.triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
    }
    const Mesh mesh = weld(soup);
    ASSERT_EQ(mesh.vertex_count(), 3u * loose);
    for (Index f = 0; f < 2 * loose; ++f) {
        EXPECT_EQ(mesh.triangles[f], mesh.triangles[f % loose]);
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(mesh.positions[mesh.triangles[f][k]], soup.points[soup.triangles[f][k]]);
        }
    }
}

TEST(Weld, RejectsOutOfRangeIndexAndNonFiniteCoordinates) {
    TriangleSoup soup;
    soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    soup.triangles = {{0, 1, 3}};
    EXPECT_THROW(weld(soup), InvalidInput);
    soup.triangles = {{0, 1, 2}};
    soup.points[1].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(weld(soup), InvalidInput);
    soup.points[1].y() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(weld(soup), InvalidInput);
}

TEST(Geometry, FaceAndVertexNormalsOfABox) {
    const Mesh mesh = test::box_mesh(2.0, 3.0, 4.0);
    const Connectivity c = build_connectivity(mesh);
    const std::vector<Vec3> fn = face_normals(mesh);
    EXPECT_TRUE(fn[0].isApprox(Vec3(0, 0, -1)));
    EXPECT_TRUE(fn[2].isApprox(Vec3(0, 0, 1)));
    const std::vector<Vec3> vn = vertex_normals(mesh, c);
    // Area weights: the mean of the incident faces' normals, each counted by its area.
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        Vec3 sum = Vec3::Zero();
        for (Index f : c.faces_around(static_cast<Index>(v))) {
            const Triangle& t = mesh.triangles[f];
            const double area = 0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]])
                                          .cross(mesh.positions[t[2]] - mesh.positions[t[0]])
                                          .norm();
            sum += area * fn[f];
        }
        EXPECT_TRUE(vn[v].isApprox(sum.normalized(), 1e-12)) << "vertex " << v;
        const Vec3 outward = (mesh.positions[v] - Vec3(1.0, 1.5, 2.0)).cwiseSign();
        EXPECT_GT(vn[v].dot(outward), 0.0);
    }
}

/// A bumpy height field over an n x n grid of vertices, two triangles a cell.
Mesh height_field(int n) {
    Mesh mesh;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            mesh.positions.emplace_back(i, j, 0.3 * std::sin(1.3 * i) * std::cos(0.7 * j));
        }
    }
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const Index a = static_cast<Index>(j * n + i), b = a + 1, c = a + n, d = c + 1;
            mesh.triangles.push_back({a, b, d});
            mesh.triangles.push_back({a, d, c});
        }
    }
    return mesh;
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

TEST(Geometry, NormalsAfterMovesAreThoseOfTheMovedMeshAndGoBackToTheInputs) {
    const Mesh input = height_field(8);
    const Connectivity c = build_connectivity(input);
    Mesh moved = input;
    std::vector<std::uint8_t> flags(input.vertex_count(), 0);
    for (Index v : {Index{9}, Index{10}, Index{45}}) {
        flags[v] = 1;
        moved.positions[v] += Vec3(0.1, -0.2, 0.35);
    }
    const SurfaceNormals before = surface_normals(input, c);
    const SurfaceNormals after = surface_normals(moved, c);
    // A vertex no moved vertex shares a face with keeps what it was given, even a wrong value:
    // only the moves' neighbourhoods are computed again.
    SurfaceNormals given = before;
    const Index far = 63;
    given.vertex[far] = Vec3(7, 7, 7);
    const SurfaceNormals found = surface_normals_after_moves(moved, c, given, flags);
    EXPECT_EQ(found.vertex[far], Vec3(7, 7, 7));
    given.vertex[far] = before.vertex[far];
    const SurfaceNormals made = surface_normals_after_moves(moved, c, given, flags);
    EXPECT_TRUE(same_bits(made.face, after.face));
    EXPECT_TRUE(same_bits(made.vertex, after.vertex));
    EXPECT_FALSE(same_bits(made.vertex, before.vertex));
    const SurfaceNormals back = surface_normals_after_moves(input, c, made, flags);
    EXPECT_TRUE(same_bits(back.face, before.face));
    EXPECT_TRUE(same_bits(back.vertex, before.vertex));
}

TEST(Geometry, AngleIsAccurateNearZeroAndStraight) {
    EXPECT_NEAR(angle_deg(Vec3(1, 0, 0), Vec3(1, 1e-9, 0).normalized()), 1e-9 * 180 / M_PI, 1e-15);
    EXPECT_NEAR(angle_deg(Vec3(1, 0, 0), Vec3(-1, 0, 0)), 180.0, 1e-12);
    EXPECT_NEAR(angle_deg(Vec3(1, 0, 0), Vec3(0, 0, 1)), 90.0, 1e-12);
}

}  // namespace
}  // namespace resharp
