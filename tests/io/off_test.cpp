#include "resharp/io/off.h"

#include <gtest/gtest.h>

#include "io/io_test_support.h"

namespace resharp::io {
namespace {

using test::expect_parse_error;

const std::string kSquare = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

TEST(OffRead, PolygonsCommentsAndFaceColours) {
    const std::string text = "OFF\n# a square and a triangle\n4 2 0\n" + kSquare +
                             "4 0 1 2 3 255 0 0\n3 0 1 2 0.5 0.5 0.5 1\n";
    const TriangleSoup soup = read_off(text, "sq.off");
    ASSERT_EQ(soup.points.size(), 4u);
    ASSERT_EQ(soup.triangles.size(), 3u);
    EXPECT_EQ(soup.triangles[1], (Triangle{0, 2, 3}));
}

TEST(OffRead, CountsOnTheHeaderLineAndColouredVertices) {
    const std::string text = "COFF 3 1 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n3 0 1 2\n";
    EXPECT_EQ(read_off(text, "c.off").triangles.size(), 1u);
}

TEST(OffReject, Defects) {
    expect_parse_error([&] { read_off("PLY\n", "h.off"); }, "h.off", "line 1",
                       "expected an 'OFF' header, found 'PLY'");
    expect_parse_error([&] { read_off("OFF\n4 -1 0\n", "n.off"); }, "n.off", "line 2",
                       "negative count");
    expect_parse_error([&] { read_off("OFF\n40 1 0\n" + kSquare, "big.off"); }, "big.off", "line 2",
                       "more than the");
    expect_parse_error([&] { read_off("OFF\n4 1 0\n0 0 0\n1 0\n", "few.off"); }, "few.off",
                       "line 4", "missing vertex coordinate");
    expect_parse_error([&] { read_off("OFF\n4 1 0\n" + kSquare + "3 0 1\n", "fi.off"); }, "fi.off",
                       "line 7", "face lists 2 of its 3 vertex indices");
    expect_parse_error([&] { read_off("OFF\n4 1 0\n" + kSquare + "2 0 1\n", "two.off"); },
                       "two.off", "line 7", "face has 2 corners");
    expect_parse_error([&] { read_off("OFF\n4 1 0\n" + kSquare + "3 0 1 4\n", "r.off"); }, "r.off",
                       "line 7", "vertex index 4 out of range (4 vertices)");
    expect_parse_error([&] { read_off("OFF\n4 2 0\n" + kSquare + "3 0 1 2\n", "t.off"); }, "t.off",
                       "line 7", "file ends after 1 of 2 faces");
    expect_parse_error([&] { read_off("OFF\n4 1 0\n" + kSquare + "3 0 1 2\n3 0 1 2\n", "x.off"); },
                       "x.off", "line 8", "unexpected data after the last face");
    expect_parse_error([&] { read_off("OFF\n4 0 0\n" + kSquare, "nf.off"); }, "nf.off", "line 2",
                       "no faces");
    expect_parse_error([&] { read_off("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "nan.off"); },
                       "nan.off", "line 4", "NaN or infinite");
    expect_parse_error([&] { read_off("OFF\n4 1 0\n" + kSquare + "3 0 1 2 1 1 1 1 1\n", "c.off"); },
                       "c.off", "line 7", "too many values");
}

}  // namespace
}  // namespace resharp::io
