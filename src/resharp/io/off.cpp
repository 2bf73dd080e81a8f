#include "resharp/io/off.h"

#include <algorithm>

#include "resharp/core/errors.h"
#include "resharp/io/detail/file_bytes.h"
#include "resharp/io/detail/mesh_checks.h"
#include "resharp/io/detail/output_buffer.h"
#include "resharp/io/detail/reader_support.h"
#include "resharp/io/detail/text_cursor.h"

namespace resharp::io {
namespace {

constexpr int kMaxExtraVertexValues = 7;  // CNOFF: nx ny nz r g b a
constexpr int kMaxFaceColourValues = 4;   // r g b a
// Every vertex and face line holds at least one token and a separator. A tighter bound would
// report a malformed line as a bad count.
constexpr std::uint64_t kMinRecordBytes = 2;

class OffReader {
public:
    OffReader(std::string_view bytes, const std::string& name)
        : bytes_(bytes), cursor_(bytes, name, '#') {}

    TriangleSoup read() {
        read_header();
        for (std::int64_t v = 0; v < vertex_count_; ++v) read_vertex(v);
        for (std::int64_t f = 0; f < face_count_; ++f) read_face(f);
        cursor_.next_line();
        if (!cursor_.only_space_left()) cursor_.fail("unexpected data after the last face");
        return std::move(soup_);
    }

private:
    void read_header() {
        const std::string_view header = cursor_.token();
        if (header != "OFF" && header != "COFF" && header != "NOFF" && header != "CNOFF") {
            cursor_.fail("expected an 'OFF' header, found " +
                         (header.empty() ? std::string("end of file") : detail::quoted(header)));
        }
        vertex_count_ = cursor_.next_integer("vertex count");
        face_count_ = cursor_.next_integer("face count");
        const std::int64_t edge_count = cursor_.next_integer("edge count");
        if (vertex_count_ < 0 || face_count_ < 0 || edge_count < 0) cursor_.fail("negative count");
        if (const std::string_view extra = cursor_.token_in_line(); !extra.empty()) {
            cursor_.fail("unexpected " + detail::quoted(extra) + " after the counts");
        }
        if (vertex_count_ >= kNoIndex) cursor_.fail("more vertices than resharp indexes");
        if (face_count_ == 0) cursor_.fail("OFF holds no faces");
        const std::uint64_t left = bytes_.size() - cursor_.offset();
        const auto vertices = static_cast<std::uint64_t>(vertex_count_);
        const auto faces = static_cast<std::uint64_t>(face_count_);
        if (!detail::fits(vertices + faces, kMinRecordBytes, left + 1)) {
            cursor_.fail("header promises " + std::to_string(vertex_count_) + " vertices and " +
                         std::to_string(face_count_) + " faces, more than the " +
                         std::to_string(left) + " bytes left can hold");
        }
        // Reserve no more than well-formed lines could fill ("0 0 0\n", "3 0 1 2\n"), so a
        // lying count costs at most a few times the file size.
        soup_.points.reserve(std::min(vertices, left / 6));
        soup_.triangles.reserve(std::min(faces, left / 8));
    }

    // The first token of the next line that has one.
    std::string_view next_record(const char* what, std::int64_t number, std::int64_t count) {
        while (cursor_.next_line()) {
            if (const std::string_view token = cursor_.token_in_line(); !token.empty())
                return token;
        }
        cursor_.fail("file ends after " + std::to_string(number) + " of " + std::to_string(count) +
                     " " + what);
    }

    // Checks that at most `limit` numbers remain on the line.
    void skip_extra_values(int limit, const char* what) {
        for (int extra = 0;; ++extra) {
            const std::string_view token = cursor_.token_in_line();
            if (token.empty()) return;
            if (extra == limit) cursor_.fail(std::string("too many values ") + what);
            cursor_.to_double(token, "extra value");
        }
    }

    void read_vertex(std::int64_t v) {
        Vec3 p;
        p[0] = cursor_.to_double(next_record("vertices", v, vertex_count_), "vertex coordinate");
        p[1] = cursor_.double_in_line("vertex coordinate");
        p[2] = cursor_.double_in_line("vertex coordinate");
        skip_extra_values(kMaxExtraVertexValues, "on a vertex line");
        soup_.points.push_back(p);
    }

    void read_face(std::int64_t f) {
        const std::int64_t corners =
            cursor_.to_integer(next_record("faces", f, face_count_), "face corner count");
        if (corners < 3) {
            cursor_.fail("face has " + std::to_string(corners) + " corners, at least 3 needed");
        }
        polygon_.clear();
        for (std::int64_t k = 0; k < corners; ++k) {
            const std::string_view token = cursor_.token_in_line();
            if (token.empty()) {
                cursor_.fail("face lists " + std::to_string(k) + " of its " +
                             std::to_string(corners) + " vertex indices");
            }
            const std::int64_t index = cursor_.to_integer(token, "vertex index");
            if (index < 0 || index >= vertex_count_) {
                cursor_.fail("vertex index " + std::to_string(index) + " out of range (" +
                             std::to_string(vertex_count_) + " vertices)");
            }
            polygon_.push_back(static_cast<Index>(index));
        }
        skip_extra_values(kMaxFaceColourValues, "after the face's vertex indices");
        detail::append_fan(polygon_, soup_.triangles);
    }

    std::string_view bytes_;
    detail::TextCursor cursor_;
    std::int64_t vertex_count_ = 0;
    std::int64_t face_count_ = 0;
    TriangleSoup soup_;
    std::vector<Index> polygon_;
};

}  // namespace

TriangleSoup read_off(std::string_view bytes, const std::string& name) {
    if (bytes.empty()) throw ParseError(name, FileLocation::line(1), "file is empty");
    return OffReader(bytes, name).read();
}

TriangleSoup read_off(std::istream& in, const std::string& name) {
    return read_off(detail::read_stream_bytes(in, name), name);
}

void write_off(std::ostream& out, const Mesh& mesh) {
    detail::require_writable(mesh);
    detail::OutputBuffer buffer(out);
    buffer.text("OFF\n");
    buffer.number(static_cast<std::int64_t>(mesh.positions.size()));
    buffer.text(' ');
    buffer.number(static_cast<std::int64_t>(mesh.triangles.size()));
    buffer.text(" 0\n");
    for (const Vec3& p : mesh.positions) {
        for (Eigen::Index i = 0; i < 3; ++i) {
            if (i > 0) buffer.text(' ');
            buffer.number(p[i]);
        }
        buffer.text('\n');
    }
    for (const Triangle& t : mesh.triangles) {
        buffer.text('3');
        for (const Index v : t) {
            buffer.text(' ');
            buffer.number(std::int64_t{v});
        }
        buffer.text('\n');
    }
}

}  // namespace resharp::io
