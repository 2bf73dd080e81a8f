#include "resharp/io/obj.h"

#include <gtest/gtest.h>

#include "io/io_test_support.h"

namespace resharp::io {
namespace {

using test::expect_parse_error;

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjRead, AllCornerForms) {
    const std::string text = kSquare +
                             "vt 0 0\nvn 0 0 1\n"
                             "f 1 2 3\nf 1/1 3/1 4/1\nf 1//1 2//1 4//1\nf 2/1/1 3/1/1 4/1/1\n";
    const TriangleSoup soup = read_obj(text, "forms.obj");
    ASSERT_EQ(soup.triangles.size(), 4u);
    EXPECT_EQ(soup.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(soup.triangles[3], (Triangle{1, 2, 3}));
}

TEST(ObjRead, NegativeIndicesCountBackFromTheLastVertex) {
    const TriangleSoup soup = read_obj(kSquare + "f -4 -3 -2\nv 5 5 5\nf -1 -2/3 -3//1\n", "n.obj");
    ASSERT_EQ(soup.triangles.size(), 2u);
    EXPECT_EQ(soup.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(soup.triangles[1], (Triangle{4, 3, 2}));
}

TEST(ObjRead, PolygonsAreFanTriangulated) {
    const TriangleSoup soup = read_obj(kSquare + "v 0.5 2 0\nf 1 2 3 5 4\n", "fan.obj");
    ASSERT_EQ(soup.triangles.size(), 3u);
    EXPECT_EQ(soup.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(soup.triangles[1], (Triangle{0, 2, 4}));
    EXPECT_EQ(soup.triangles[2], (Triangle{0, 4, 3}));
}

TEST(ObjRead, SkipsOtherRecordsCommentsAndExtraVertexValues) {
    const std::string text =
        "# exported\r\nmtllib a.mtl\no part\ng side\ns off\nusemtl steel\n"
        "v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0   # trailing comment\n\n"
        "l 1 2\nf 1 2 3 # face\n";
    const TriangleSoup soup = read_obj(text, "skip.obj");
    EXPECT_EQ(soup.points.size(), 3u);
    EXPECT_EQ(soup.triangles.size(), 1u);
}

TEST(ObjReject, Defects) {
    expect_parse_error([&] { read_obj(kSquare + "f 0 1 2\n", "z.obj"); }, "z.obj", "line 5",
                       "vertex index 0");
    expect_parse_error([&] { read_obj(kSquare + "f 1 2 5\n", "r.obj"); }, "r.obj", "line 5",
                       "vertex index 5 out of range (4 vertices defined so far)");
    expect_parse_error([&] { read_obj(kSquare + "f 1 2 -5\n", "m.obj"); }, "m.obj", "line 5",
                       "vertex index -5 out of range");
    expect_parse_error([&] { read_obj("f 1 2 3\n" + kSquare, "fw.obj"); }, "fw.obj", "line 1",
                       "out of range (0 vertices defined so far)");
    expect_parse_error([&] { read_obj(kSquare + "f 1 2 x\n", "g.obj"); }, "g.obj", "line 5",
                       "expected an integer for vertex index, found 'x'");
    expect_parse_error([&] { read_obj(kSquare + "f 1 2/ 3\n", "s.obj"); }, "s.obj", "line 5",
                       "malformed face corner '2/'");
    expect_parse_error([&] { read_obj(kSquare + "f 1 2\n", "two.obj"); }, "two.obj", "line 5",
                       "face has 2 corners");
    expect_parse_error([&] { read_obj(kSquare + "garbage 1 2\n", "k.obj"); }, "k.obj", "line 5",
                       "unknown OBJ record 'garbage'");
    expect_parse_error([&] { read_obj("v 0 0\n", "few.obj"); }, "few.obj", "line 1",
                       "missing vertex coordinate");
    expect_parse_error([&] { read_obj("v 0 0 inf\n", "inf.obj"); }, "inf.obj", "line 1",
                       "NaN or infinite");
    expect_parse_error([&] { read_obj("v 0 0 0 1 2 3 4 5\n", "many.obj"); }, "many.obj", "line 1",
                       "too many values");
    expect_parse_error([&] { read_obj(kSquare, "nof.obj"); }, "nof.obj", "line 4", "no faces");
    expect_parse_error([&] { read_obj("", "e.obj"); }, "e.obj", "line 1", "file is empty");
    expect_parse_error([&] { read_obj(kSquare + "f 1 2 99999999999999999999\n", "o.obj"); },
                       "o.obj", "line 5", "out of range");
}

}  // namespace
}  // namespace resharp::io
