// The float box around a box of doubles (restoration/outer_box.h): it must meet every box its
// box meets, at any scale the doubles reach, and it still tells boxes well apart.

#include "resharp/restoration/outer_box.h"

#include <gtest/gtest.h>

#include <random>

namespace resharp {
namespace {

Box3 box_of(const Vec3& a, const Vec3& b) { return Box3(a.cwiseMin(b), a.cwiseMax(b)); }

TEST(OuterBox, MeetsABoxTouchingItAtABoundNoFloatHolds) {
    const Box3 box(Vec3(0, 0, 0), Vec3(0.1, 0.1, 0.1));  // 0.1: between two floats
    EXPECT_TRUE(OuterBox(box).may_meet(Box3(Vec3(0.1, 0.1, 0.1), Vec3(1, 1, 1))));
    EXPECT_TRUE(OuterBox(box).may_meet(Box3(Vec3(-1, -1, -1), Vec3(0, 0, 0))));
    EXPECT_FALSE(OuterBox(box).may_meet(Box3(Vec3(0.2, 0, 0), Vec3(1, 1, 1))));
    EXPECT_FALSE(OuterBox().may_meet(box));  // empty
}

TEST(OuterBox, MeetsEveryBoxItsBoxMeetsAtAnyScale) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (double scale : {1e-300, 1e-42, 1e-3, 1.0, 1e7, 1e38, 1e39, 1e300}) {
        SCOPED_TRACE(scale);
        int met = 0, apart = 0;
        for (int n = 0; n < 2000; ++n) {
            auto point = [&] {
                Vec3 p;
                for (int k = 0; k < 3; ++k) p[k] = scale * unit(random);  // in a stated order
                return p;
            };
            const Box3 a = box_of(point(), point()), b = box_of(point(), point());
            // A box that touches `a` at its corner, exactly.
            const Box3 touching = box_of(a.max(), a.max() + scale * Vec3(0.5, 0.5, 0.5));
            EXPECT_TRUE(OuterBox(a).may_meet(touching));
            if (a.intersects(b)) {
                ++met;
                EXPECT_TRUE(OuterBox(a).may_meet(b));
            } else if (!OuterBox(a).may_meet(b)) {
                ++apart;
            }
        }
        EXPECT_GT(met, 0);
        EXPECT_GT(apart, 0);  // the float box still parts boxes well apart
    }
}

}  // namespace
}  // namespace resharp
