#include "resharp/io/ply.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

#include "io/io_test_support.h"

namespace resharp::io {
namespace {

using test::append;
using test::expect_parse_error;

const std::string kAsciiSquare =
    "ply\nformat ascii 1.0\ncomment a square\nelement vertex 4\n"
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";

TEST(PlyRead, AsciiQuadIsFanTriangulated) {
    const TriangleSoup soup = read_ply(kAsciiSquare, "sq.ply");
    ASSERT_EQ(soup.points.size(), 4u);
    ASSERT_EQ(soup.triangles.size(), 2u);
    EXPECT_EQ(soup.triangles[1], (Triangle{0, 2, 3}));
}

// Binary big-endian, properties in unusual order and types, an extra element with lists.
std::string big_endian_file() {
    std::string bytes =
        "ply\r\nformat binary_big_endian 1.0\r\n"
        "element vertex 3\r\nproperty uchar red\r\nproperty double z\r\nproperty float x\r\n"
        "property list uint8 int16 junk\r\nproperty float32 y\r\nproperty int surface\r\n"
        "element material 2\r\nproperty list ushort float values\r\n"
        "element face 1\r\nproperty short tag\r\nproperty list int uint vertex_index\r\n"
        "end_header\r\n";
    const auto big = std::endian::big;
    for (int v = 0; v < 3; ++v) {
        append(bytes, std::uint8_t(10 * v), big);
        append(bytes, double(v) + 0.25, big);  // z
        append(bytes, float(v == 1), big);     // x
        append(bytes, std::uint8_t{2}, big);   // junk list: 2 items
        append(bytes, std::int16_t{-1}, big);
        append(bytes, std::int16_t{7}, big);
        append(bytes, float(v == 2), big);  // y
        append(bytes, std::int32_t{-5 * v}, big);
    }
    for (int m = 0; m < 2; ++m) {
        append(bytes, std::uint16_t(m), big);
        for (int i = 0; i < m; ++i) append(bytes, 1.0f, big);
    }
    append(bytes, std::int16_t{42}, big);
    append(bytes, std::int32_t{3}, big);
    for (std::uint32_t i : {0u, 1u, 2u}) append(bytes, i, big);
    return bytes;
}

TEST(PlyRead, BigEndianAnyPropertyOrderAndSkippedElements) {
    const TriangleSoup soup = read_ply(big_endian_file(), "be.ply");
    ASSERT_EQ(soup.points.size(), 3u);
    EXPECT_EQ(soup.points[0], Vec3(0, 0, 0.25));
    EXPECT_EQ(soup.points[1], Vec3(1, 0, 1.25));
    EXPECT_EQ(soup.points[2], Vec3(0, 1, 2.25));
    ASSERT_EQ(soup.triangles.size(), 1u);
    EXPECT_EQ(soup.triangles[0], (Triangle{0, 1, 2}));
}

TEST(PlyRead, KeepsExtraScalarPropertiesByName) {
    const PlyMesh mesh = read_ply_with_properties(big_endian_file(), "be.ply");
    ASSERT_EQ(mesh.vertex_properties.size(), 2u);
    EXPECT_EQ(mesh.vertex_properties[0].name, "red");
    EXPECT_EQ(*mesh.vertex_property("surface"), (std::vector<double>{0, -5, -10}));
    EXPECT_EQ(*mesh.face_property("tag"), (std::vector<double>{42}));
    EXPECT_EQ(mesh.vertex_property("junk"), nullptr);
}

TEST(PlyRead, FacePropertiesRepeatPerTriangleOfAPolygon) {
    std::string text = kAsciiSquare;
    text.replace(text.find("end_header"), 0, "property uchar red\n");
    text.replace(text.find("4 0 1 2 3"), 9, "4 0 1 2 3 200");
    const PlyMesh mesh = read_ply_with_properties(text, "c.ply");
    EXPECT_EQ(*mesh.face_property("red"), (std::vector<double>{200, 200}));
}

TEST(PlyRead, StreamOverloadAndZeroPropertyElements) {
    std::string text = kAsciiSquare;
    text.replace(text.find("end_header"), 0, "element nothing 999999999999\n");
    std::istringstream in(text);
    EXPECT_EQ(read_ply(in, "s.ply").triangles.size(), 2u);
}

std::string little_endian_header(const std::string& elements) {
    return "ply\nformat binary_little_endian 1.0\n" + elements + "end_header\n";
}

const std::string kFloatVertices =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
const std::string kFaces = "element face 1\nproperty list uchar int vertex_indices\n";

std::string little_endian_triangle(float bad_y = 0, std::int32_t last_index = 2) {
    std::string bytes = little_endian_header(kFloatVertices + kFaces);
    for (int v = 0; v < 3; ++v) {
        append(bytes, float(v == 1));
        append(bytes, v == 2 ? 1.0f : (v == 1 ? bad_y : 0.0f));
        append(bytes, 0.0f);
    }
    append(bytes, std::uint8_t{3});
    for (std::int32_t i : {0, 1, last_index}) append(bytes, i);
    return bytes;
}

TEST(PlyRead, BinaryLittleEndian) {
    const TriangleSoup soup = read_ply(little_endian_triangle(), "le.ply");
    EXPECT_EQ(soup.triangles.size(), 1u);
}

TEST(PlyReject, BinaryDefectsNameTheByte) {
    const std::size_t body = little_endian_header(kFloatVertices + kFaces).size();
    expect_parse_error(
        [&] { read_ply(little_endian_triangle(std::numeric_limits<float>::infinity()), "i.ply"); },
        "i.ply", "byte " + std::to_string(body + 16), "property 'y' is NaN or infinite");
    expect_parse_error([&] { read_ply(little_endian_triangle(0, 3), "r.ply"); }, "r.ply",
                       "byte " + std::to_string(body + 36 + 1 + 8),
                       "vertex index 3 out of range (3 vertices)");
    expect_parse_error([&] { read_ply(little_endian_triangle(0, -1), "neg.ply"); }, "neg.ply",
                       "byte " + std::to_string(body + 36 + 1 + 8), "vertex index -1 out of range");
    std::string cut = little_endian_triangle();
    cut.pop_back();
    expect_parse_error([&] { read_ply(cut, "cut.ply"); }, "cut.ply",
                       "byte " + std::to_string(body + 36 + 1 + 8), "file truncated");
    expect_parse_error([&] { read_ply(little_endian_triangle() + "x", "tail.ply"); }, "tail.ply",
                       "byte " + std::to_string(body + 36 + 13), "1 unexpected bytes");
}

TEST(PlyReject, ListLengthsAndCounts) {
    std::string two = little_endian_triangle();
    two[two.size() - 13] = 2;  // the face's corner count
    const std::size_t body = little_endian_header(kFloatVertices + kFaces).size();
    expect_parse_error([&] { read_ply(two, "two.ply"); }, "two.ply",
                       "byte " + std::to_string(body + 36), "face has 2 corners");

    std::string huge = little_endian_header(
        kFloatVertices + "element face 1\nproperty list uint int vertex_indices\n");
    const std::size_t huge_body = huge.size();
    for (int i = 0; i < 9; ++i) append(huge, 0.0f);
    append(huge, std::uint32_t{0xffffffffu});
    append(huge, std::int32_t{0});
    expect_parse_error([&] { read_ply(huge, "huge.ply"); }, "huge.ply",
                       "byte " + std::to_string(huge_body + 44), "file truncated");

    std::string skipped = little_endian_header("element junk 1\nproperty list int double d\n" +
                                               kFloatVertices + kFaces);
    const std::size_t skipped_body = skipped.size();
    append(skipped, std::int32_t{1 << 30});
    skipped.append(49, '\0');  // enough for the vertices and the face the header declares
    expect_parse_error([&] { read_ply(skipped, "sk.ply"); }, "sk.ply",
                       "byte " + std::to_string(skipped_body + 4),
                       "list of 1073741824 values runs past the end of the file");

    expect_parse_error(
        [&] {
            read_ply(little_endian_header(
                         "element vertex 1000000000\nproperty float x\nproperty float y\n"
                         "property float z\n" +
                         kFaces),
                     "count.ply");
        },
        "count.ply", "line 3", "element 'vertex' promises 1000000000 rows of at least 12 bytes");
}

TEST(PlyReject, HeaderDefectsNameTheLine) {
    const auto header_error = [](const std::string& header, const std::string& location,
                                 const std::string& reason) {
        expect_parse_error([&] { read_ply(header + "end_header\n", "h.ply"); }, "h.ply", location,
                           reason);
    };
    header_error("plx\n", "line 1", "not a PLY file");
    header_error("ply\nformat binary 1.0\n", "line 2", "unknown PLY format 'binary'");
    header_error("ply\nformat ascii 2.0\n", "line 2", "unsupported PLY version");
    header_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float128 x\n", "line 4",
                 "unknown PLY type 'float128'");
    header_error("ply\nformat ascii 1.0\nproperty float x\n", "line 3",
                 "property before any element");
    header_error("ply\nformat ascii 1.0\nelement vertex -3\n", "line 3", "negative element count");
    header_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "line 5",
                 "vertex element has no scalar 'y' property");
    header_error("ply\nformat ascii 1.0\n" + kFloatVertices, "line 7",
                 "header declares no 'face' element");
    header_error("ply\nformat ascii 1.0\n" + kFloatVertices +
                     "element face 1\nproperty list float int vertex_indices\n",
                 "line 8", "list count type must be an integer");
    header_error("ply\nformat ascii 1.0\nbogus\n", "line 3", "unknown header keyword 'bogus'");
    expect_parse_error([&] { read_ply("ply\nformat ascii 1.0\n", "eof.ply"); }, "eof.ply", "line 2",
                       "missing 'end_header'");
}

TEST(PlyReject, AsciiBodyDefectsNameTheLine) {
    const auto body_error = [](const std::string& from, const std::string& to,
                               const std::string& location, const std::string& reason) {
        std::string text = kAsciiSquare;
        text.replace(text.find(from), from.size(), to);
        expect_parse_error([&] { read_ply(text, "a.ply"); }, "a.ply", location, reason);
    };
    body_error("1 1 0\n", "1 nan 0\n", "line 13", "NaN or infinite");
    body_error("4 0 1 2 3", "4 0 1 2 4", "line 15", "vertex index 4 out of range");
    body_error("4 0 1 2 3", "256 0 1 2 3", "line 15",
               "value 256 of property 'vertex_indices' out of range for uchar");
    body_error("4 0 1 2 3", "4 0 1 2", "line 15", "unexpected end of file");
    body_error("4 0 1 2 3", "4 0 1 2 3 7", "line 15", "unexpected data after the last element");
    body_error("1 0 0\n", "1 zero 0\n", "line 12", "expected a number for y, found 'zero'");
}

}  // namespace
}  // namespace resharp::io
