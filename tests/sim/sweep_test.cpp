#include "resharp/sim/sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace resharp::sim {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Interval> cut(const SweptVolume& v, const Ray& ray) {
    std::vector<Interval> out;
    v.intersect(ray, out);
    return out;
}

ToolMotion line(const Vec3& a, const Vec3& b) {
    return {.kind = ToolMotion::Kind::Line, .start = a, .end = b};
}

ToolMotion arc(const Eigen::Vector2d& c, double r, double z, double from, double sweep) {
    const double to = from + sweep;
    return {.kind = ToolMotion::Kind::Arc,
            .start = Vec3(c.x() + r * std::cos(from), c.y() + r * std::sin(from), z),
            .end = Vec3(c.x() + r * std::cos(to), c.y() + r * std::sin(to), z),
            .center = c,
            .radius = r,
            .start_angle = from,
            .sweep = sweep};
}

const Tool kFlat = Tool::make(ToolShape::FlatEnd, 6.0, 0.0, 20.0);
const Tool kBall = Tool::make(ToolShape::BallEnd, 6.0, 0.0, 20.0);
const Tool kBull = Tool::make(ToolShape::BullNose, 6.0, 1.0, 20.0);

TEST(SweptVolume, FlatSlotByHand) {
    const SweptVolume v(kFlat, line(Vec3(0, 0, 5), Vec3(10, 0, 5)), 0);
    auto z = cut(v, Ray{2, Vec3(5, 1, 0)});
    ASSERT_EQ(z.size(), 1u);
    EXPECT_EQ(z[0].enter.t, 5.0);
    EXPECT_EQ(z[0].enter.normal, Vec3(0, 0, -1));
    EXPECT_EQ(z[0].enter.surface, tool_surface_id(0, ToolPart::Bottom));
    EXPECT_EQ(z[0].exit.t, 25.0);
    EXPECT_TRUE(cut(v, Ray{2, Vec3(5, 3.5, 0)}).empty());

    auto x = cut(v, Ray{0, Vec3(0, 1, 6)});
    ASSERT_EQ(x.size(), 1u);
    EXPECT_NEAR(x[0].enter.t, -std::sqrt(8.0), 1e-14);
    EXPECT_NEAR(x[0].exit.t, 10 + std::sqrt(8.0), 1e-14);
    EXPECT_NEAR((x[0].enter.normal - Vec3(-std::sqrt(8.0) / 3, 1.0 / 3, 0)).norm(), 0, 1e-14);
    auto y = cut(v, Ray{1, Vec3(5, 0, 6)});
    ASSERT_EQ(y.size(), 1u);
    EXPECT_EQ(y[0].enter.t, -3.0);
    EXPECT_EQ(y[0].exit.normal, Vec3(0, 1, 0));
    EXPECT_EQ(y[0].exit.surface, tool_surface_id(0, ToolPart::Side));
    // The bottom plane counts as inside the tool, the top plane as outside.
    EXPECT_EQ(cut(v, Ray{1, Vec3(5, 0, 5)}).size(), 1u);
    EXPECT_TRUE(cut(v, Ray{1, Vec3(5, 0, 25)}).empty());
}

TEST(SweptVolume, BallAndBullNoseBottomsByHand) {
    const SweptVolume ball(kBall, line(Vec3(0, 0, 5), Vec3(10, 0, 5)), 3);
    auto z = cut(ball, Ray{2, Vec3(5, 1, 0)});
    ASSERT_EQ(z.size(), 1u);
    EXPECT_NEAR(z[0].enter.t, 8 - std::sqrt(8.0), 1e-14);
    EXPECT_NEAR((z[0].enter.normal - Vec3(0, 1.0 / 3, -std::sqrt(8.0) / 3)).norm(), 0, 1e-14);
    EXPECT_EQ(z[0].enter.surface, tool_surface_id(3, ToolPart::Corner));
    auto y = cut(ball, Ray{1, Vec3(5, 0, 6)});  // one above the tip: radius sqrt(5)
    ASSERT_EQ(y.size(), 1u);
    EXPECT_NEAR(y[0].exit.t, std::sqrt(5.0), 1e-14);

    const SweptVolume bull(kBull, line(Vec3(0, 0, 5), Vec3(10, 0, 5)), 0);
    z = cut(bull, Ray{2, Vec3(5, 2.5, 0)});
    ASSERT_EQ(z.size(), 1u);
    EXPECT_NEAR(z[0].enter.t, 5 + 1 - std::sqrt(0.75), 1e-14);
    z = cut(bull, Ray{2, Vec3(5, 1.5, 0)});
    EXPECT_EQ(z[0].enter.t, 5.0);
}

TEST(SweptVolume, QuarterArcByHand) {
    const Tool small = Tool::make(ToolShape::FlatEnd, 2.0, 0.0, 10.0);
    for (double sign : {1.0, -1.0}) {  // G3 from 0° to 90°, and G2 from 90° to 0°
        const ToolMotion m =
            sign > 0 ? arc({0, 0}, 5, 0, 0, kPi / 2) : arc({0, 0}, 5, 0, kPi / 2, -kPi / 2);
        const SweptVolume v(small, m, 0);
        auto x = cut(v, Ray{0, Vec3(0, 3, 0.5)});
        ASSERT_EQ(x.size(), 1u);
        EXPECT_NEAR(x[0].enter.t, std::sqrt(7.0), 1e-13);
        EXPECT_NEAR(x[0].exit.t, std::sqrt(27.0), 1e-13);
        EXPECT_NEAR((x[0].enter.normal - Vec3(-std::sqrt(7.0) / 4, -0.75, 0)).norm(), 0, 1e-13);
        EXPECT_TRUE(cut(v, Ray{0, Vec3(0, -3, 0.5)}).empty());
        EXPECT_EQ(cut(v, Ray{2, Vec3(5.5 / std::sqrt(2.0), 5.5 / std::sqrt(2.0), 0)}).size(), 1u);
        EXPECT_TRUE(cut(v, Ray{2, Vec3(-5, 0, 0)}).empty());
    }
    const SweptVolume full(small, arc({0, 0}, 5, 0, 0.3, 2 * kPi), 0);
    EXPECT_EQ(cut(full, Ray{0, Vec3(0, 3, 0.5)}).size(), 2u);
}

TEST(SweptVolume, FlatRampFloorIsTheSweptRim) {
    const Tool flat = Tool::make(ToolShape::FlatEnd, 4.0, 0.0, 20.0);
    const SweptVolume v(flat, line(Vec3(0, 0, 0), Vec3(10, 0, -5)), 0);
    auto z = cut(v, Ray{2, Vec3(5, 0, 0)});
    ASSERT_EQ(z.size(), 1u);
    EXPECT_NEAR(z[0].enter.t, -3.5, 1e-14);
    EXPECT_NEAR((z[0].enter.normal - Vec3(-1, 0, -2).normalized()).norm(), 0, 1e-14);
    EXPECT_EQ(z[0].enter.surface, tool_surface_id(0, ToolPart::BottomRim));
}

/// The union of static tool copies at n points along the motion, as a reference.
std::vector<Interval> sampled(const Tool& tool, const ToolMotion& m, const Ray& ray, int n) {
    std::vector<Interval> all;
    for (int i = 0; i <= n; ++i) {
        const double f = static_cast<double>(i) / n;
        Vec3 p = m.start + f * (m.end - m.start);
        if (m.kind == ToolMotion::Kind::Arc) {
            const double a = m.start_angle + f * m.sweep;
            p = Vec3(m.center.x() + m.radius * std::cos(a), m.center.y() + m.radius * std::sin(a),
                     m.start.z());
        }
        const SweptVolume copy(tool, line(p, p), 0);
        copy.intersect(ray, all);
    }
    std::sort(all.begin(), all.end(),
              [](const Interval& a, const Interval& b) { return a.enter.t < b.enter.t; });
    std::vector<Interval> merged;
    for (const Interval& x : all) {
        if (!merged.empty() && x.enter.t <= merged.back().exit.t) {
            merged.back().exit.t = std::max(merged.back().exit.t, x.exit.t);
        } else {
            merged.push_back(x);
        }
    }
    return merged;
}

struct Case {
    const char* name;
    Tool tool;
    ToolMotion motion;
    double tolerance = 1e-3;  ///< the reference's own sampling error, mm
    bool is_exact = true;     ///< false where the sweep itself samples (bull-nose ramps)
};

class SweepAgainstSampling : public ::testing::TestWithParam<Case> {};

TEST_P(SweepAgainstSampling, ExactIntervalsHugDenselySampledCopies) {
    const Case& c = GetParam();
    const SweptVolume exact(c.tool, c.motion, 0);
    const Box3 box = exact.bounds();
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int compared = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Ray ray{trial % 3, Vec3::Zero()};
        for (int a = 0; a < 3; ++a) {
            if (a != ray.axis) ray.origin[a] = box.min()[a] + u(rng) * box.sizes()[a];
        }
        const auto e = cut(exact, ray);
        const auto s = sampled(c.tool, c.motion, ray, 4000);
        // Sampling misses slivers thinner than its error; compare the ends of what it finds.
        if (s.size() != e.size()) {
            ASSERT_GE(e.size(), s.size());
            continue;
        }
        for (std::size_t i = 0; i < e.size(); ++i) {
            EXPECT_NEAR(e[i].enter.t, s[i].enter.t, c.tolerance) << c.name << " trial " << trial;
            EXPECT_NEAR(e[i].exit.t, s[i].exit.t, c.tolerance) << c.name << " trial " << trial;
            if (c.is_exact) {  // the exact volume holds every sampled copy
                EXPECT_LE(e[i].enter.t, s[i].enter.t + 1e-9);
                EXPECT_GE(e[i].exit.t, s[i].exit.t - 1e-9);
            }
            EXPECT_NEAR(e[i].enter.normal.norm(), 1.0, 1e-12);
            EXPECT_NEAR(e[i].exit.normal.norm(), 1.0, 1e-12);
        }
        ++compared;
    }
    EXPECT_GT(compared, 50);
}

INSTANTIATE_TEST_SUITE_P(
    Tools, SweepAgainstSampling,
    ::testing::Values(Case{"flat_line", kFlat, line(Vec3(1, 2, 3), Vec3(9, -4, 3))},
                      Case{"ball_line", kBall, line(Vec3(1, 2, 3), Vec3(9, -4, 3))},
                      Case{"bull_line", kBull, line(Vec3(1, 2, 3), Vec3(9, -4, 3))},
                      Case{"flat_ramp", kFlat, line(Vec3(1, 2, 3), Vec3(9, -4, -1)),
                           5e-3},  // rim: coarser reference
                      Case{"ball_ramp", kBall, line(Vec3(1, 2, 3), Vec3(9, -4, 5)), 5e-3},
                      Case{"bull_ramp", kBull, line(Vec3(1, 2, 3), Vec3(9, -4, 1)), 0.05, false},
                      Case{"flat_plunge", kFlat, line(Vec3(1, 2, 8), Vec3(1, 2, 3))},
                      Case{"ball_plunge", kBall, line(Vec3(1, 2, 3), Vec3(1, 2, 8))},
                      Case{"flat_arc", kFlat, arc({1, 2}, 7, 3, 0.4, 2.1)},
                      Case{"ball_arc", kBall, arc({1, 2}, 7, 3, 0.4, -4.1)},
                      Case{"bull_arc_tight", kBull, arc({1, 2}, 2, 3, 1.0, 5.0)}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace resharp::sim
