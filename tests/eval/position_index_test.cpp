#include "resharp/eval/position_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace resharp::eval {
namespace {

// A double that rounds to the same float finds its point; one a float step away does not.
TEST(PositionIndex, MatchesByFloatRounding) {
    const std::vector<Vec3> points{Vec3(0.1, 0.2, 0.3), Vec3(1, 2, 3)};
    const PositionIndex index(points);
    EXPECT_EQ(index.find(Vec3(0.1, 0.2, 0.3)), Index(0));
    const Vec3 as_float(double(float(0.1)), double(float(0.2)), double(float(0.3)));
    EXPECT_EQ(index.find(as_float), Index(0));
    EXPECT_EQ(index.find(Vec3(1, 2, 3)), Index(1));
    const double next = double(std::nextafter(3.0f, 4.0f));
    EXPECT_FALSE(index.find(Vec3(1, 2, next)).has_value());
    EXPECT_FALSE(index.find(Vec3(2, 1, 3)).has_value());
}

TEST(PositionIndex, ExactCoordinatesKeepPointsThatRoundAlikeApart) {
    const std::vector<Vec3> points{Vec3(5, 5, 5), Vec3(5, 5, 5 + 1e-12), Vec3(6, 6, 6)};
    const PositionIndex index(points);
    EXPECT_EQ(index.find(Vec3(5, 5, 5)), Index(0));
    EXPECT_EQ(index.find(Vec3(5, 5, 5 + 1e-12)), Index(1));
    EXPECT_EQ(index.find(Vec3(6, 6, 6)), Index(2));
    // A float (as binary STL holds it) finds the first of the points that round to it.
    EXPECT_EQ(index.find(Vec3(5, 5, double(float(5 + 2e-12)))), Index(0));
}

// A point that needs a double (a restored point written to PLY a few micrometres from an input
// vertex) matches only exactly: it is not that vertex, though both round to one float.
TEST(PositionIndex, APointOnlyADoubleHoldsMatchesOnlyExactly) {
    const std::vector<Vec3> points{Vec3(0.1, 0.2, 0.3)};
    const PositionIndex index(points);
    EXPECT_FALSE(index.find(Vec3(0.1, 0.2, 0.3 + 1e-9)).has_value());
    EXPECT_EQ(double(float(0.3 + 1e-9)), double(float(0.3)));  // the case: they round alike
}

}  // namespace
}  // namespace resharp::eval
