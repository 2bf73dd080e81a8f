#include "resharp/eval/surface_distance.h"

#include <gtest/gtest.h>

#include "resharp/core/errors.h"
#include "resharp/eval/surface_samples.h"
#include "resharp/sim/solids.h"

namespace resharp::eval {
namespace {

// Box [0.1, 0.9] x [0.1, 0.6] x [0.15, 0.7]: no grid line of pitch 0.25 through the origin
// meets a face diagonal, a face or an edge, so each crossing belongs to exactly one triangle.
const Vec3 kLo(0.1, 0.1, 0.15), kHi(0.9, 0.6, 0.7);

Mesh box_mesh(const Vec3& lo, const Vec3& hi) {
    Mesh m;
    for (int i = 0; i < 8; ++i) {
        m.positions.push_back(
            Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
    }
    m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

sim::GridSpec grid(double pitch) {
    return {.origin = Vec3::Zero(), .pitch = pitch, .counts = {5, 4, 4}};
}

SurfaceSamples exact_box(double pitch) {
    const sim::ConvexPolytope box = sim::axis_box(sim::Box3(kLo, kHi), 0);
    return sample_exact_surface(sim::sample_solid(grid(pitch), box));
}

// z-rays through (0.25|0.5|0.75, 0.25|0.5) meet bottom and top: 12; x-rays through
// (y, z) in (0.25|0.5) x (0.25|0.5): 8; y-rays through (z, x) in (0.25|0.5) x (0.25|0.5|0.75): 12.
TEST(SurfaceSamples, MeshSamplesAreTheExactCrossingsWhenTheMeshIsTheSurface) {
    const SurfaceSamples exact = exact_box(0.25);
    const SurfaceSamples mesh = sample_mesh(box_mesh(kLo, kHi), grid(0.25));
    ASSERT_EQ(exact.size(), 32u);
    ASSERT_EQ(mesh.size(), 32u);
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        double best = 1e9;
        for (std::size_t j = 0; j < exact.size(); ++j) {
            if (mesh.normals[i].dot(exact.normals[j]) > 0.999) {
                best = std::min(best, (mesh.points[i] - exact.points[j]).norm());
            }
        }
        EXPECT_LT(best, 1e-12) << i;
    }
}

TEST(SurfaceMetrics, SurfaceAgainstItselfIsPerfect) {
    const Mesh mesh = box_mesh(kLo, kHi);
    const SurfaceMetricsOptions o{.pitch = 1.0, .edge_radius = 0.3};
    const SurfaceMetrics m =
        compare_surfaces(mesh, sample_mesh(mesh, grid(0.25)), exact_box(0.25), o);
    EXPECT_NEAR(m.chamfer_l1, 0.0, 1e-12);
    EXPECT_NEAR(m.hausdorff, 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(m.normal_consistency, 1.0);
    EXPECT_DOUBLE_EQ(m.f1, 1.0);
    EXPECT_GT(m.edges_ndc.exact_edge_samples, 0u);
    EXPECT_EQ(m.edges_ndc.exact_edge_samples, m.edges_ndc.mesh_edge_samples);
    EXPECT_NEAR(m.edges_ndc.ecd, 0.0, 1e-20);
    EXPECT_DOUBLE_EQ(m.edges_ndc.ef1, 1.0);
    EXPECT_DOUBLE_EQ(m.edges_dihedral.ef1, 1.0);
}

// Every face moved out by d: each exact sample lies exactly d from the grown box (its foot is
// on the face above it), so the exact side of every distance is d.
TEST(SurfaceMetrics, OffsetBoxIsItsOffsetAway) {
    const double d = 0.01;
    const Mesh grown = box_mesh(kLo - Vec3::Constant(d), kHi + Vec3::Constant(d));
    const SurfaceMetricsOptions o{.pitch = 1.0, .edge_radius = 0.3, .f1_threshold = 0.005};
    const SurfaceMetrics m =
        compare_surfaces(grown, sample_mesh(grown, grid(0.25)), exact_box(0.25), o);
    // The mesh side: each mesh sample's nearest exact sample is the crossing of its own ray,
    // d away (the next one on the face is a pitch away).
    EXPECT_NEAR(m.chamfer_l1, d, 1e-12);
    EXPECT_NEAR(m.hausdorff, d, 1e-12);
    EXPECT_NEAR(m.chamfer_l2, 2 * d * d, 1e-15);
    EXPECT_DOUBLE_EQ(m.f1, 0.0);  // every distance is at least d > threshold
}

TEST(SurfaceMetrics, RefusesEmptySamples) {
    const Mesh mesh = box_mesh(kLo, kHi);
    EXPECT_THROW(compare_surfaces(mesh, {}, exact_box(0.25)), InvalidInput);
}

}  // namespace
}  // namespace resharp::eval
