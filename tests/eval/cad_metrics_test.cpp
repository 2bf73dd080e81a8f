#include "resharp/eval/cad_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cube_creases.h"
#include "resharp/core/errors.h"
#include "resharp/eval/exact_creases.h"
#include "support/simple_meshes.h"

namespace resharp::eval {
namespace {

constexpr double kSide = 10.0;
const double kDiagonal = kSide * std::sqrt(3.0);

CurveSamples cube_creases() { return test::cube_creases(kSide); }

/// The convex polytope with these outward face normals around `vertices`: each face is the
/// vertices on its support plane, fanned in counter-clockwise order about the normal.
Mesh convex_hull_mesh(const std::vector<Vec3>& vertices, const std::vector<Vec3>& normals) {
    Mesh m{vertices, {}};
    for (const Vec3& n : normals) {
        double top = -1e300;
        for (const Vec3& v : vertices) top = std::max(top, n.dot(v));
        std::vector<Index> face;
        Vec3 centre = Vec3::Zero();
        for (Index i = 0; i < vertices.size(); ++i) {
            if (n.dot(vertices[i]) > top - 1e-9) face.push_back(i), centre += vertices[i];
        }
        centre /= double(face.size());
        const Vec3 u = (vertices[face[0]] - centre).normalized(), w = n.cross(u);
        const auto angle = [&](Index i) {
            const Vec3 d = vertices[i] - centre;
            return std::atan2(d.dot(w), d.dot(u));
        };
        std::sort(face.begin(), face.end(), [&](Index a, Index b) { return angle(a) < angle(b); });
        for (std::size_t k = 1; k + 1 < face.size(); ++k) {
            m.triangles.push_back({face[0], face[k], face[k + 1]});
        }
    }
    return m;
}

/// The cube with every edge cut by a 45-degree chamfer reaching w along both faces.
Mesh chamfered_cube(double w) {
    std::vector<Vec3> vertices, normals;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 s(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
        const Vec3 c = 0.5 * kSide * (Vec3::Ones() + s);
        for (int a = 0; a < 3; ++a) {
            Vec3 v = c - w * s;  // in by w along the two other axes
            v[a] = c[a];
            vertices.push_back(v);
        }
        normals.push_back(s.normalized());
    }
    for (int a = 0; a < 3; ++a) {
        for (const double sign : {-1.0, 1.0}) normals.push_back(sign * Vec3::Unit(a));
        const int b = (a + 1) % 3;
        for (const double sa : {-1.0, 1.0}) {
            for (const double sb : {-1.0, 1.0}) {
                Vec3 n = Vec3::Zero();
                n[a] = sa, n[b] = sb;
                normals.push_back(n.normalized());
            }
        }
    }
    return convex_hull_mesh(vertices, normals);
}

CreaseMetrics score(const Mesh& mesh) {
    return compare_creases(cube_creases(), sample_mesh_creases(mesh, 30.0, 0.05),
                           {.tolerance = 1e-3, .unit = kDiagonal});
}

TEST(MeshCreases, BoxEdgesButNotItsFaceDiagonals) {
    const CurveSamples c = sample_mesh_creases(test::box_mesh(1, 2, 3), 30.0, 0.1);
    EXPECT_NEAR(c.total_length(), 4 * (1 + 2 + 3), 1e-12);
    for (double w : c.weights) EXPECT_LE(w, 0.1 + 1e-12);
    EXPECT_THROW(sample_mesh_creases(test::box_mesh(), 30.0, 0.0), InvalidInput);
}

TEST(CreaseMetrics, ExactCubeMeshHasNoEdgeError) {
    const CreaseMetrics m = score(test::box_mesh(kSide, kSide, kSide));
    EXPECT_LT(m.ecd, 1e-20);
    EXPECT_DOUBLE_EQ(m.ef1, 1.0);
    EXPECT_NEAR(m.true_length, 12 * kSide / kDiagonal, 0.01 * 12 * kSide / kDiagonal);
    EXPECT_NEAR(m.length_ratio, 1.0, 0.01);
}

TEST(CreaseMetrics, BoxGrownWithinTauScoresOneWithItsOffsetAsDistance) {
    // Faces moved out by e: every edge lies e * sqrt(2) from the true one, inside tau.
    const double e = 0.005;
    Mesh grown = test::box_mesh(kSide + 2 * e, kSide + 2 * e, kSide + 2 * e);
    for (Vec3& p : grown.positions) p -= Vec3::Constant(e);
    const CreaseMetrics m = score(grown);
    EXPECT_DOUBLE_EQ(m.ef1, 1.0);
    const double d = e * std::sqrt(2.0) / kDiagonal;
    // Both ways about d (the grown edges run on past the true corners by e: a little more).
    EXPECT_NEAR(m.ecd, 2 * d * d, 0.05 * 2 * d * d);
}

TEST(CreaseMetrics, ChamferedCubeFindsNoTrueEdgeAndDoublesTheLength) {
    const double w = 0.5;
    const CreaseMetrics m = score(chamfered_cube(w));
    // Each chamfer strip leaves two creases w from the true edge (45 degrees to the faces) and
    // meets the corner triangles at 35.3 degrees: 24 (side - 2w) + 24 w sqrt(2).
    const double length = 24 * (kSide - 2 * w) + 24 * w * std::sqrt(2.0);
    EXPECT_NEAR(m.mesh_length, length / kDiagonal, 1e-9);
    EXPECT_NEAR(m.length_ratio, length / (12 * kSide), 0.02);
    EXPECT_DOUBLE_EQ(m.precision, 0.0);
    EXPECT_DOUBLE_EQ(m.recall, 0.0);
    EXPECT_DOUBLE_EQ(m.ef1, 0.0);
    EXPECT_GT(m.ecd, score(test::box_mesh(kSide, kSide, kSide)).ecd);
    // The creases lie 0.5 from the true edges, farther than the default 1 % of the diagonal
    // (0.17), all but the corner triangles' near ends.
    EXPECT_GT(m.stray_length, 0.9 * m.mesh_length);
    EXPECT_EQ(score(test::box_mesh(kSide, kSide, kSide)).stray_length, 0.0);
}

TEST(CreaseMetrics, EmptySidesScoreByDefinition) {
    const CurveSamples none;
    const CreaseMetrics both = compare_creases(none, none);
    EXPECT_EQ(both.ecd, 0.0);
    EXPECT_EQ(both.ef1, 1.0);
    const CreaseMetrics phantom =
        compare_creases(none, sample_mesh_creases(test::box_mesh(), 30.0, 0.1));
    EXPECT_TRUE(std::isnan(phantom.ecd));
    EXPECT_EQ(phantom.precision, 0.0);
    EXPECT_EQ(phantom.ef1, 0.0);
    EXPECT_DOUBLE_EQ(phantom.stray_length, phantom.mesh_length);
    EXPECT_TRUE(std::isnan(phantom.length_ratio));
}

TEST(CadMetrics, DividesDistancesByTheDiagonal) {
    SurfaceMetrics s;
    s.chamfer_l1 = 0.2;
    s.hausdorff = 0.5;
    s.normal_consistency = 0.9;
    const Mesh cube = test::box_mesh(kSide, kSide, kSide);
    const CadMetrics m = measure_cad_part(cube, s, cube_creases(), kDiagonal);
    EXPECT_DOUBLE_EQ(m.chamfer, 0.2 / kDiagonal);
    EXPECT_DOUBLE_EQ(m.hausdorff, 0.5 / kDiagonal);
    EXPECT_DOUBLE_EQ(m.normal_consistency, 0.9);
    EXPECT_DOUBLE_EQ(m.creases.ef1, 1.0);
    EXPECT_THROW(measure_cad_part(cube, s, cube_creases(), 0.0), InvalidInput);
}

}  // namespace
}  // namespace resharp::eval
