// Inputs no mesher should write (issue: property tests, item 4): a random triangle soup,
// collinear points, thousands of tiny components, half the faces missing, sixty faces on one
// edge. restore() finishes on each and, by the harm criteria checked apart from its own, makes
// nothing worse.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "resharp/pipeline/restore.h"
#include "support/invariants.h"
#include "support/simple_meshes.h"
#include "support/small_parts.h"

namespace resharp {
namespace {

TEST(HostileInput, RandomTriangleSoup) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> coordinate(0.0, 10.0);
    Mesh soup;
    for (int i = 0; i < 500; ++i) {
        soup.positions.emplace_back(coordinate(random), coordinate(random), coordinate(random));
    }
    std::uniform_int_distribution<Index> vertex(0, 499);
    for (int i = 0; i < 600; ++i)
        soup.triangles.push_back({vertex(random), vertex(random), vertex(random)});
    test::expect_no_harm(soup, restore(soup), {});
}

TEST(HostileInput, CollinearPoints) {
    Mesh line;
    for (int i = 0; i < 300; ++i) line.positions.push_back(Vec3(1.0, 2.0, 3.0) * (0.01 * i));
    for (Index i = 0; i + 2 < 300; ++i) line.triangles.push_back({i, i + 1, i + 2});
    for (Index i = 0; i + 7 < 300; i += 3) line.triangles.push_back({i + 7, i, i + 3});
    const RestoreResult r = restore(line);
    EXPECT_TRUE(r.report.output_unchanged);
    test::expect_no_harm(line, r, {});
}

TEST(HostileInput, ThousandsOfTinyComponents) {
    // 2,500 boxes 0.01 mm wide, 0.05 mm apart: 30,000 triangles.
    const Mesh tiny = test::box_mesh(0.01, 0.01, 0.01);
    Mesh many;
    for (int i = 0; i < 2500; ++i) {
        const Vec3 at(0.05 * (i % 50), 0.05 * (i / 50), 0.0);
        const Index first = static_cast<Index>(many.vertex_count());
        for (const Vec3& p : tiny.positions) many.positions.push_back(p + at);
        for (Triangle t : tiny.triangles) {
            for (Index& v : t) v += first;
            many.triangles.push_back(t);
        }
    }
    const RestoreResult r = restore(many);
    EXPECT_EQ(r.report.input.components, 2500u);
    test::expect_no_harm(many, r, {});
}

TEST(HostileInput, HalfTheFacesMissing) {
    for (test::SmallPart part : test::kSmallParts) {
        SCOPED_TRACE(to_string(part));
        Mesh half = test::small_part(part);
        std::mt19937 random(23);
        std::shuffle(half.triangles.begin(), half.triangles.end(), random);
        half.triangles.resize(half.triangles.size() / 2);
        test::expect_no_harm(half, restore(half), {});
    }
}

TEST(HostileInput, SixtyFacesOnOneEdge) {
    Mesh fan = test::small_part(test::SmallPart::PocketedBlock);
    const RestoreResult clean = restore(fan);
    // 58 more faces on the edge of face 0, their far corners on a circle of 1 mm about it.
    const Triangle t = fan.triangles[0];
    const Vec3 a = fan.positions[t[0]], b = fan.positions[t[1]];
    const Vec3 axis = (b - a).normalized();
    const Vec3 u = axis.unitOrthogonal(), w = axis.cross(u);
    for (int k = 0; k < 58; ++k) {
        const double angle = 2.0 * std::numbers::pi * (k + 0.5) / 58.0;
        fan.positions.push_back((a + b) / 2 + std::cos(angle) * u + std::sin(angle) * w);
        fan.triangles.push_back({t[1], t[0], static_cast<Index>(fan.vertex_count() - 1)});
    }
    const RestoreResult r = restore(fan);
    EXPECT_EQ(r.report.input.nonmanifold_edges, 1u);
    // The rest of the part is still restored, all but the points near the fan.
    EXPECT_GT(r.report.edge_points_inserted, clean.report.edge_points_inserted * 9 / 10);
    test::expect_no_harm(fan, r, {});
}

}  // namespace
}  // namespace resharp
