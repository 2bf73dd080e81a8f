#include "resharp/io/stl.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "resharp/core/errors.h"
#include "resharp/io/detail/byte_cursor.h"
#include "resharp/io/detail/file_bytes.h"
#include "resharp/io/detail/mesh_checks.h"
#include "resharp/io/detail/output_buffer.h"
#include "resharp/io/detail/reader_support.h"
#include "resharp/io/detail/text_cursor.h"

namespace resharp::io {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kCountEnd = kHeaderBytes + 4;
constexpr std::size_t kRecordBytes = 50;  // normal, 3 vertices (12 floats), 2 attribute bytes
// Three soup points per triangle, indexed by 32-bit Index.
constexpr std::uint64_t kMaxTriangles = kNoIndex / 3;

bool starts_with_solid(std::string_view bytes) {
    const std::size_t first = bytes.find_first_not_of(" \t\r\n");
    return first != std::string_view::npos &&
           detail::equals_ignoring_case(bytes.substr(first, 5), "solid");
}

bool is_binary(std::string_view bytes) {
    if (!starts_with_solid(bytes)) return true;
    if (bytes.size() >= kCountEnd) {
        const auto count =
            detail::load<std::uint32_t>(bytes.data() + kHeaderBytes, std::endian::little);
        if (bytes.size() == kCountEnd + std::uint64_t{count} * kRecordBytes) return true;
    }
    // An ASCII STL is text and never holds a NUL; almost every binary one does.
    return bytes.find('\0') != std::string_view::npos;
}

TriangleSoup read_binary(std::string_view bytes, const std::string& name) {
    detail::ByteCursor cursor(bytes, name);
    cursor.take(kHeaderBytes, "the 80-byte binary STL header");
    const std::uint32_t count =
        cursor.read<std::uint32_t>(std::endian::little, "the triangle count");
    if (count == 0) cursor.fail_at(kHeaderBytes, "binary STL holds no triangles");
    if (!detail::fits(count, kRecordBytes, cursor.remaining())) {
        cursor.fail_at(kHeaderBytes, "header promises " + std::to_string(count) + " triangles (" +
                                         std::to_string(std::uint64_t{count} * kRecordBytes) +
                                         " bytes) but only " + std::to_string(cursor.remaining()) +
                                         " bytes follow (file truncated?)");
    }
    if (count > kMaxTriangles) cursor.fail_at(kHeaderBytes, "more triangles than resharp indexes");
    const std::size_t end = kCountEnd + std::size_t{count} * kRecordBytes;
    if (bytes.size() > end) {
        cursor.fail_at(end, std::to_string(bytes.size() - end) +
                                " unexpected bytes after the last of " + std::to_string(count) +
                                " triangles");
    }
    TriangleSoup soup;
    soup.points.reserve(std::size_t{count} * 3);
    soup.triangles.reserve(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const std::size_t record = cursor.offset();
        const char* vertices = cursor.take(kRecordBytes, "a triangle").data() + 12;
        for (std::size_t k = 0; k < 9; k += 3) {
            Vec3 p;
            for (std::size_t axis = 0; axis < 3; ++axis) {
                const float value =
                    detail::load<float>(vertices + 4 * (k + axis), std::endian::little);
                if (!std::isfinite(value)) {
                    cursor.fail_at(record + 12 + 4 * (k + axis), "vertex coordinate of triangle " +
                                                                     std::to_string(t) +
                                                                     " is NaN or infinite");
                }
                p[static_cast<Eigen::Index>(axis)] = value;
            }
            soup.points.push_back(p);
        }
        const Index base = 3 * t;
        soup.triangles.push_back({base, base + 1, base + 2});
    }
    return soup;
}

// One "facet normal ... endfacet" block; the "facet" keyword has been consumed.
void read_ascii_facet(detail::TextCursor& cursor, TriangleSoup& soup) {
    cursor.expect("normal");
    for (int i = 0; i < 3; ++i) cursor.next_double("facet normal component");
    cursor.expect("outer");
    cursor.expect("loop");
    if (soup.triangles.size() == kMaxTriangles) cursor.fail("more triangles than resharp indexes");
    const Index base = static_cast<Index>(soup.points.size());
    for (int k = 0; k < 3; ++k) {
        const std::string_view keyword = cursor.token();
        if (!detail::equals_ignoring_case(keyword, "vertex")) {
            cursor.fail(
                "facet has " + std::to_string(k) + " vertices, STL facets need exactly 3 (found " +
                (keyword.empty() ? std::string("end of file") : detail::quoted(keyword)) + ")");
        }
        Vec3 p;
        for (Eigen::Index axis = 0; axis < 3; ++axis)
            p[axis] = cursor.next_double("vertex coordinate");
        soup.points.push_back(p);
    }
    const std::string_view end = cursor.token();
    if (detail::equals_ignoring_case(end, "vertex")) {
        cursor.fail("facet has more than 3 vertices, STL facets need exactly 3");
    }
    if (!detail::equals_ignoring_case(end, "endloop")) {
        cursor.fail("expected 'endloop', found " +
                    (end.empty() ? std::string("end of file") : detail::quoted(end)));
    }
    cursor.expect("endfacet");
    soup.triangles.push_back({base, base + 1, base + 2});
}

// One or more "solid NAME ... endsolid NAME" blocks (some tools concatenate solids).
TriangleSoup read_ascii(std::string_view bytes, const std::string& name) {
    detail::TextCursor cursor(bytes, name);
    TriangleSoup soup;
    cursor.expect("solid");
    cursor.next_line();  // the rest of the line is the solid's name
    for (;;) {
        const std::string_view keyword = cursor.token();
        if (detail::equals_ignoring_case(keyword, "facet")) {
            read_ascii_facet(cursor, soup);
        } else if (detail::equals_ignoring_case(keyword, "endsolid")) {
            cursor.next_line();
            const std::string_view next = cursor.token();
            if (next.empty()) break;
            if (!detail::equals_ignoring_case(next, "solid")) {
                cursor.fail("expected 'solid' or end of file after 'endsolid', found " +
                            detail::quoted(next));
            }
            cursor.next_line();
        } else if (keyword.empty()) {
            cursor.fail("missing 'endsolid' (unexpected end of file)");
        } else {
            cursor.fail("expected 'facet' or 'endsolid', found " + detail::quoted(keyword));
        }
    }
    if (soup.triangles.empty()) cursor.fail("ASCII STL holds no triangles");
    return soup;
}

Vec3 unit_normal(const Mesh& mesh, const Triangle& t) {
    const Vec3& a = mesh.positions[t[0]];
    const Vec3 n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    const double length = n.norm();
    return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

void require_float_range(const Mesh& mesh) {
    constexpr double kMax = std::numeric_limits<float>::max();
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (mesh.positions[v].cwiseAbs().maxCoeff() > kMax) {
            throw InvalidInput("vertex " + std::to_string(v) +
                               " has a coordinate beyond the float range STL stores");
        }
    }
}

void write_binary(detail::OutputBuffer& out, const Mesh& mesh) {
    std::string header = "binary STL written by resharp";
    header.resize(kHeaderBytes, ' ');
    out.text(header);
    out.binary(static_cast<std::uint32_t>(mesh.triangles.size()));
    for (const Triangle& t : mesh.triangles) {
        const Vec3 n = unit_normal(mesh, t);
        for (Eigen::Index i = 0; i < 3; ++i) out.binary(static_cast<float>(n[i]));
        for (const Index v : t) {
            for (Eigen::Index i = 0; i < 3; ++i)
                out.binary(static_cast<float>(mesh.positions[v][i]));
        }
        out.binary(std::uint16_t{0});
    }
}

// Doubles in their shortest exact form: ASCII STL then round-trips exactly through resharp,
// and readers that parse floats get the nearest float, as from a binary file.
void write_numbers(detail::OutputBuffer& out, const Vec3& p) {
    for (Eigen::Index i = 0; i < 3; ++i) {
        out.text(' ');
        out.number(p[i]);
    }
    out.text('\n');
}

void write_ascii(detail::OutputBuffer& out, const Mesh& mesh) {
    out.text("solid resharp\n");
    for (const Triangle& t : mesh.triangles) {
        out.text("  facet normal");
        write_numbers(out, unit_normal(mesh, t));
        out.text("    outer loop\n");
        for (const Index v : t) {
            out.text("      vertex");
            write_numbers(out, mesh.positions[v]);
        }
        out.text("    endloop\n  endfacet\n");
    }
    out.text("endsolid resharp\n");
}

}  // namespace

TriangleSoup read_stl(std::string_view bytes, const std::string& name) {
    if (bytes.empty()) throw ParseError(name, FileLocation::byte(0), "file is empty");
    return is_binary(bytes) ? read_binary(bytes, name) : read_ascii(bytes, name);
}

TriangleSoup read_stl(std::istream& in, const std::string& name) {
    return read_stl(detail::read_stream_bytes(in, name), name);
}

void write_stl(std::ostream& out, const Mesh& mesh, Encoding encoding) {
    detail::require_writable(mesh);
    require_float_range(mesh);
    if (encoding == Encoding::Binary &&
        mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw InvalidInput("binary STL holds at most 2^32-1 triangles");
    }
    detail::OutputBuffer buffer(out);
    if (encoding == Encoding::Binary) {
        write_binary(buffer, mesh);
    } else {
        write_ascii(buffer, mesh);
    }
}

}  // namespace resharp::io
