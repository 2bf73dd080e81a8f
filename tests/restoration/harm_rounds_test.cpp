// The harm check's later rounds: with `changed` flags only the split faces within two rings of a
// changed face are judged.
#include <gtest/gtest.h>

#include "resharp/core/errors.h"
#include "resharp/restoration/harm_check.h"
#include "resharp/restoration/split.h"
#include "strip.h"

namespace resharp {
namespace {

/// Two copies of the strip far apart (faces 0, 1 and 2, 3), each split at a point that turns a
/// piece over (as in HarmCheck.APieceTurnedOverIsHarm).
struct TwoStrips {
    test::Strip strips;
    SplitMesh split;
};

TwoStrips two_turned_strips() {
    const test::Strip one = test::make_strip();
    TwoStrips t;
    t.strips.mesh = one.mesh;
    for (const Vec3& p : one.mesh.positions) t.strips.mesh.positions.push_back(p + Vec3(0, 0, 100));
    for (const Triangle& f : one.mesh.triangles)
        t.strips.mesh.triangles.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
    t.strips.rebuild();
    SharpPoints points = test::points_on_edge_a1_b0(one);
    // The same slots on the second strip, with a second point.
    const Vec3 turned(-2.0, 3.0, 0.75);
    points.points = {turned, turned + Vec3(0, 0, 100)};
    PointSlots slots(4);
    for (Index h = 0; h < 6; ++h) {
        const Index p = points.slots.edge_point(h);
        if (p == kNoIndex) continue;
        slots.set_edge_point(h, 0);
        slots.set_edge_point(h + 6, 1);
    }
    t.split = split_faces(t.strips.mesh, points.points, slots);
    return t;
}

TEST(HarmRounds, AFullCheckFindsBothStrips) {
    const TwoStrips t = two_turned_strips();
    const HarmReport r = check_harm(t.strips.surface(), t.split);
    EXPECT_EQ(r.harmful_faces, (std::vector<Index>{0, 1, 2, 3}));
}

TEST(HarmRounds, OnlyTheFacesNearAChangedOneAreJudged) {
    const TwoStrips t = two_turned_strips();
    const std::vector<std::uint8_t> first{1, 0, 0, 0}, second{0, 0, 0, 1}, none{0, 0, 0, 0};
    EXPECT_EQ(check_harm(t.strips.surface(), t.split, {}, first).harmful_faces,
              (std::vector<Index>{0, 1}));
    EXPECT_EQ(check_harm(t.strips.surface(), t.split, {}, second).harmful_faces,
              (std::vector<Index>{2, 3}));
    const HarmReport nothing = check_harm(t.strips.surface(), t.split, {}, none);
    EXPECT_TRUE(nothing.is_harmless());
    EXPECT_EQ(nothing.turned + nothing.folded + nothing.crossing, 0u);
}

TEST(HarmRounds, ChangeFlagsMustCoverEveryFace) {
    const TwoStrips t = two_turned_strips();
    const std::vector<std::uint8_t> short_flags{1, 0};
    EXPECT_THROW(check_harm(t.strips.surface(), t.split, {}, short_flags), InvalidInput);
}

}  // namespace
}  // namespace resharp
