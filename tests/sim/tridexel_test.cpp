#include "resharp/sim/tridexel.h"

#include <gtest/gtest.h>

#include "resharp/core/errors.h"
#include "resharp/sim/solids.h"

namespace resharp::sim {
namespace {

Crossing at(double t, int surface, double nx = 0.0) { return {t, Vec3(nx, 0, 0), surface}; }
Interval span(double a, double b, int sa, int sb) { return {at(a, sa, -1), at(b, sb, 1)}; }

RayIntervals ray_of(std::vector<Interval> intervals) {
    RayIntervals r;
    r.assign(intervals.data(), intervals.data() + intervals.size());
    return r;
}

TEST(GridEnclosing, PutsOneNodeStrictlyOutsideEverySide) {
    const Box3 box(Vec3(0, 0, 0), Vec3(10, 5, 2));
    const GridSpec g = grid_enclosing(box, 0.5);
    for (int a = 0; a < 3; ++a) {
        EXPECT_LT(g.node(a, 0), box.min()[a]);
        EXPECT_GT(g.node(a, g.counts[a] - 1), box.max()[a]);
        EXPECT_GE(g.node(a, 1), box.min()[a]);  // only one outside node
    }
    EXPECT_EQ(g.counts[0], 23);  // -0.5 .. 10.5
}

TEST(GridEnclosing, RejectsBadPitchAndEmptyBox) {
    EXPECT_THROW(grid_enclosing(Box3(Vec3::Zero(), Vec3::Ones()), 0.0), InvalidInput);
    EXPECT_THROW(grid_enclosing(Box3(), 0.5), InvalidInput);
}

TEST(SubtractIntervals, CutsTheMiddleAndTakesTheCuttersIdsAndReversedNormals) {
    RayIntervals solid = ray_of({span(0, 10, 1, 2)});
    const std::vector<Interval> removed{span(3, 4, 7, 8)};
    std::vector<Interval> scratch;
    subtract_intervals(solid, removed, scratch);
    ASSERT_EQ(solid.size(), 2u);
    EXPECT_EQ(solid[0].enter.surface, 1);
    EXPECT_EQ(solid[0].exit.t, 3.0);
    EXPECT_EQ(solid[0].exit.surface, 7);
    EXPECT_EQ(solid[0].exit.normal.x(), 1.0);  // the cutter's entry normal -x, reversed
    EXPECT_EQ(solid[1].enter.t, 4.0);
    EXPECT_EQ(solid[1].enter.surface, 8);
    EXPECT_EQ(solid[1].enter.normal.x(), -1.0);
    EXPECT_EQ(solid[1].exit.surface, 2);
}

TEST(SubtractIntervals, HandlesOverhangsWholeRemovalAndSeveralCuts) {
    std::vector<Interval> scratch;
    RayIntervals solid = ray_of({span(0, 2, 1, 2), span(5, 9, 3, 4)});
    const std::vector<Interval> cuts{span(-1, 1, 7, 8), span(1.5, 6, 9, 10), span(7, 7.5, 11, 12)};
    subtract_intervals(solid, cuts, scratch);
    ASSERT_EQ(solid.size(), 3u);
    EXPECT_EQ(solid[0].enter.t, 1.0);
    EXPECT_EQ(solid[0].exit.t, 1.5);
    EXPECT_EQ(solid[1].enter.t, 6.0);
    EXPECT_EQ(solid[1].exit.t, 7.0);
    EXPECT_EQ(solid[2].enter.t, 7.5);
    EXPECT_EQ(solid[2].exit.t, 9.0);

    RayIntervals gone = ray_of({span(0, 2, 1, 2)});
    const std::vector<Interval> all{span(-1, 3, 7, 8)};
    subtract_intervals(gone, all, scratch);
    EXPECT_TRUE(gone.empty());
}

TEST(SubtractIntervals, ExactTiesKeepTheExistingEnd) {
    std::vector<Interval> scratch;
    RayIntervals solid = ray_of({span(0, 2, 1, 2)});
    const std::vector<Interval> touching{span(2, 3, 7, 8)};
    subtract_intervals(solid, touching, scratch);
    ASSERT_EQ(solid.size(), 1u);
    EXPECT_EQ(solid[0].exit.surface, 2);
}

TEST(SubtractIntervals, SpillsBeyondTheInlineCapacity) {
    std::vector<Interval> scratch;
    RayIntervals solid = ray_of({span(0, 10, 1, 2)});
    const std::vector<Interval> comb{span(1, 2, 3, 3), span(3, 4, 3, 3), span(5, 6, 3, 3)};
    subtract_intervals(solid, comb, scratch);
    ASSERT_EQ(solid.size(), 4u);
    EXPECT_EQ(solid[3].enter.t, 6.0);
    EXPECT_EQ(solid[3].exit.t, 10.0);
}

TEST(Perturbation, BoundaryPointsFacingMinusDeltaCountAsInside) {
    EXPECT_TRUE(boundary_is_inside(Vec3(0, 0, -1)));
    EXPECT_FALSE(boundary_is_inside(Vec3(0, 0, 1)));
    EXPECT_TRUE(boundary_is_inside(Vec3(-0.1, 0.9, 0.9)));
    EXPECT_FALSE(boundary_is_inside(Vec3(0, 1e-300, -1)));
}

TEST(ConvexPolytope, BoxRaysGetFaceIdsAndPlanesOnRaysFollowThePerturbation) {
    const ConvexPolytope box = axis_box(Box3(Vec3(0, 0, 0), Vec3(4, 3, 2)), 10);
    std::vector<Interval> out;
    box.intersect(Ray{0, Vec3(0, 1, 1)}, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].enter.t, 0.0);
    EXPECT_EQ(out[0].enter.surface, 10 + kMinX);
    EXPECT_EQ(out[0].exit.t, 4.0);
    EXPECT_EQ(out[0].exit.surface, 10 + kMaxX);
    out.clear();
    box.intersect(Ray{0, Vec3(0, 1, 0)}, out);  // on the bottom face (normal -z): inside
    EXPECT_EQ(out.size(), 1u);
    out.clear();
    box.intersect(Ray{0, Vec3(0, 1, 2)}, out);  // on the top face (normal +z): outside
    EXPECT_TRUE(out.empty());
}

TEST(ConvexPolytope, RejectsUnboundedSets) {
    EXPECT_THROW(ConvexPolytope({{Vec3::UnitZ(), 1.0, 0}}), InvalidInput);
}

TEST(ZCylinder, CrossingsLieOnTheCylinderWithRadialNormals) {
    const ZCylinder c({.center = {1, 2}, .radius = 2, .z_min = 0, .z_max = 3});
    std::vector<Interval> out;
    c.intersect(Ray{0, Vec3(0, 3, 1)}, out);
    ASSERT_EQ(out.size(), 1u);
    for (const Crossing& x : {out[0].enter, out[0].exit}) {
        const Vec3 p = Ray{0, Vec3(0, 3, 1)}.point(x.t);
        EXPECT_NEAR((p.head<2>() - Eigen::Vector2d(1, 2)).norm(), 2.0, 1e-14);
        EXPECT_NEAR(x.normal.norm(), 1.0, 1e-14);
        EXPECT_NEAR(x.normal.dot(p - Vec3(1, 2, p.z())), 2.0, 1e-14);
    }
    out.clear();
    c.intersect(Ray{2, Vec3(1.5, 2, 0)}, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].enter.t, 0.0);
    EXPECT_EQ(out[0].exit.t, 3.0);
}

TEST(SubtractInOrder, EqualsOneByOneSubtraction) {
    const ConvexPolytope stock = axis_box(Box3(Vec3(0.1, 0.1, 0.1), Vec3(20, 20, 10)), 0);
    const GridSpec spec = grid_enclosing(stock.bounds(), 0.5);
    std::vector<Sphere> balls;
    for (int k = 0; k < 40; ++k) {
        balls.emplace_back(Vec3(0.5 * k, 10 + 5 * std::sin(k), 10), 3.0, 100 + k);
    }
    DexelGrid one_by_one = sample_solid(spec, stock);
    for (const Sphere& b : balls) subtract(one_by_one, b);
    DexelGrid batched = sample_solid(spec, stock);
    std::vector<const Solid*> volumes;
    for (const Sphere& b : balls) volumes.push_back(&b);
    std::size_t calls = 0;
    subtract_in_order(batched, volumes, [&](std::size_t, std::size_t) { ++calls; });
    EXPECT_GT(calls, 0u);
    for (int a = 0; a < 3; ++a) {
        for (std::size_t r = 0; r < spec.ray_count(a); ++r) {
            const RayIntervals& x = one_by_one.rays[a][r];
            const RayIntervals& y = batched.rays[a][r];
            ASSERT_EQ(x.size(), y.size());
            for (std::size_t i = 0; i < x.size(); ++i) {
                EXPECT_EQ(x[i].enter.t, y[i].enter.t);
                EXPECT_EQ(x[i].exit.surface, y[i].exit.surface);
            }
        }
    }
}

}  // namespace
}  // namespace resharp::sim
