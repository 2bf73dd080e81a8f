#include "resharp/io/stl.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

#include "io/io_test_support.h"

namespace resharp::io {
namespace {

using test::append;
using test::expect_parse_error;

// A binary STL of `count` records (as many as `triangles` gives, the rest zero) after `header`.
std::string binary_stl(const std::string& header, std::uint32_t count,
                       const std::vector<std::array<float, 9>>& triangles) {
    std::string bytes = header;
    bytes.resize(80, ' ');
    append(bytes, count);
    for (const auto& t : triangles) {
        for (int i = 0; i < 3; ++i) append(bytes, 0.0f);  // normal, ignored
        for (const float c : t) append(bytes, c);
        append(bytes, std::uint16_t{0});
    }
    return bytes;
}

const std::array<float, 9> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

TEST(StlRead, BinaryWhoseHeaderStartsWithSolid) {
    const std::string bytes =
        binary_stl("solid exported by a CAD system", 2, {kTriangle, kTriangle});
    const TriangleSoup soup = read_stl(bytes, "part.stl");
    ASSERT_EQ(soup.triangles.size(), 2u);
    ASSERT_EQ(soup.points.size(), 6u);
    EXPECT_EQ(soup.points[1], Vec3(1, 0, 0));
    EXPECT_EQ(soup.triangles[1], (Triangle{3, 4, 5}));
}

TEST(StlRead, TruncatedBinaryWhoseHeaderStartsWithSolidIsStillBinary) {
    std::string bytes = binary_stl("solid x", 2, {kTriangle, kTriangle});
    bytes.resize(bytes.size() - 10);
    expect_parse_error([&] { read_stl(bytes, "cut.stl"); }, "cut.stl", "byte 80",
                       "header promises 2 triangles (100 bytes) but only 90 bytes follow");
}

TEST(StlRead, Ascii) {
    const std::string text =
        "solid part\n"
        "  facet normal 0 0 1\n    outer loop\n"
        "      vertex 0 0 0\n      vertex 1.5e0 0 0\n      vertex +0 -2.25 0\n"
        "    endloop\n  endfacet\n"
        "endsolid part\n";
    const TriangleSoup soup = read_stl(text, "a.stl");
    ASSERT_EQ(soup.triangles.size(), 1u);
    EXPECT_EQ(soup.points[1], Vec3(1.5, 0, 0));
    EXPECT_EQ(soup.points[2], Vec3(0, -2.25, 0));
}

TEST(StlRead, AsciiUpperCaseCrlfAndSeveralSolids) {
    const std::string facet =
        "FACET NORMAL 0 0 1\r\nOUTER LOOP\r\nVERTEX 0 0 0\r\nVERTEX 1 0 0\r\nVERTEX 0 1 0\r\n"
        "ENDLOOP\r\nENDFACET\r\n";
    const std::string text = "SOLID a\r\n" + facet + "ENDSOLID a\r\nsolid b\n" + facet + "endsolid";
    EXPECT_EQ(read_stl(text, "multi.stl").triangles.size(), 2u);
}

TEST(StlRead, StreamOverload) {
    std::istringstream in(binary_stl("", 1, {kTriangle}));
    EXPECT_EQ(read_stl(in, "stream.stl").triangles.size(), 1u);
}

TEST(StlReject, BinaryCountBeyondFileSize) {
    const std::string bytes = binary_stl("", 4000000000u, {kTriangle});
    expect_parse_error([&] { read_stl(bytes, "big.stl"); }, "big.stl", "byte 80",
                       "header promises 4000000000 triangles");
}

TEST(StlReject, BinaryTrailingBytes) {
    std::string bytes = binary_stl("", 1, {kTriangle});
    bytes += "xx";
    expect_parse_error([&] { read_stl(bytes, "t.stl"); }, "t.stl", "byte 134",
                       "2 unexpected bytes after the last of 1 triangles");
}

TEST(StlReject, BinaryNaNNamesTheCoordinateByte) {
    std::array<float, 9> bad = kTriangle;
    bad[4] = std::numeric_limits<float>::quiet_NaN();  // second vertex, y
    const std::string bytes = binary_stl("", 2, {kTriangle, bad});
    // Record 1 starts at 84 + 50; its vertices 12 bytes later; y of vertex 1 is float 4.
    expect_parse_error([&] { read_stl(bytes, "nan.stl"); }, "nan.stl", "byte 162",
                       "NaN or infinite");
}

TEST(StlReject, BinaryShortHeaderAndZeroTriangles) {
    expect_parse_error([&] { read_stl(std::string(50, '\x01'), "s.stl"); }, "s.stl", "byte 0",
                       "file truncated");
    expect_parse_error([&] { read_stl(binary_stl("", 0, {}), "z.stl"); }, "z.stl", "byte 80",
                       "no triangles");
    expect_parse_error([&] { read_stl("", "e.stl"); }, "e.stl", "byte 0", "file is empty");
}

TEST(StlReject, AsciiDefects) {
    const std::string head = "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n";
    expect_parse_error([&] { read_stl(head + "vertex 1 nan 0\n", "n.stl"); }, "n.stl", "line 5",
                       "NaN or infinite");
    expect_parse_error([&] { read_stl(head + "vertex 1 0 0\nendloop\n", "v.stl"); }, "v.stl",
                       "line 6", "facet has 2 vertices");
    expect_parse_error(
        [&] { read_stl(head + "vertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n", "m.stl"); }, "m.stl",
        "line 7", "more than 3 vertices");
    expect_parse_error([&] { read_stl(head + "vertex 1 0x 0\n", "g.stl"); }, "g.stl", "line 5",
                       "expected a number for vertex coordinate, found '0x'");
    expect_parse_error([&] { read_stl(head + "vertex 1 0 0\nvertex 0 1", "t.stl"); }, "t.stl",
                       "line 6", "unexpected end of file");
    expect_parse_error([&] { read_stl("solid x\nendsolid x\n", "e.stl"); }, "e.stl", "line 2",
                       "no triangles");
    expect_parse_error([&] { read_stl("solid x\nfacet normal 0 0 1\n", "f.stl"); }, "f.stl",
                       "line 2", "expected 'outer', found end of file");
    expect_parse_error([&] { read_stl("solid x\nhello\n", "h.stl"); }, "h.stl", "line 2",
                       "expected 'facet' or 'endsolid', found 'hello'");
}

TEST(StlWrite, BinaryHeaderDoesNotStartWithSolid) {
    const Mesh mesh = test::box_mesh();
    std::ostringstream out;
    write_stl(out, mesh, Encoding::Binary);
    const std::string bytes = out.str();
    ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
    EXPECT_NE(bytes.substr(0, 5), "solid");
}

TEST(StlWrite, FacetNormalsAreUnitOutwardNormals) {
    const Mesh mesh = test::box_mesh(2, 3, 4);
    std::ostringstream out;
    write_stl(out, mesh, Encoding::Ascii);
    // The first triangle (0, 2, 1) lies in z = 0 and faces down.
    EXPECT_NE(out.str().find("facet normal 0 0 -1\n"), std::string::npos)
        << out.str().substr(0, 80);
}

TEST(StlWrite, RefusesCoordinatesBeyondFloat) {
    Mesh mesh = test::box_mesh();
    mesh.positions[0].x() = 1e300;
    std::ostringstream out;
    EXPECT_THROW(write_stl(out, mesh, Encoding::Binary), InvalidInput);
}

}  // namespace
}  // namespace resharp::io
