#include "resharp/io/obj.h"

#include <algorithm>
#include <array>

#include "resharp/core/errors.h"
#include "resharp/io/detail/file_bytes.h"
#include "resharp/io/detail/mesh_checks.h"
#include "resharp/io/detail/output_buffer.h"
#include "resharp/io/detail/reader_support.h"
#include "resharp/io/detail/text_cursor.h"

namespace resharp::io {
namespace {

// Records that carry no triangle geometry; skipped whole.
constexpr std::array<std::string_view, 32> kSkippedRecords = {
    "vt",   "vn",    "vp",       "g",        "o",    "s",          "usemtl",    "mtllib",
    "l",    "p",     "cstype",   "deg",      "bmat", "step",       "curv",      "curv2",
    "surf", "parm",  "trim",     "hole",     "scrv", "sp",         "end",       "con",
    "mg",   "bevel", "c_interp", "d_interp", "lod",  "shadow_obj", "trace_obj", "maplib"};

constexpr int kMaxExtraVertexValues = 4;  // w, or an r g b colour, or both

class ObjReader {
public:
    ObjReader(std::string_view bytes, const std::string& name) : cursor_(bytes, name, '#') {}

    TriangleSoup read() {
        do {
            read_record();
        } while (cursor_.next_line());
        if (soup_.triangles.empty()) cursor_.fail("OBJ holds no faces");
        return std::move(soup_);
    }

private:
    void read_record() {
        const std::string_view keyword = cursor_.token_in_line();
        if (keyword.empty()) return;
        if (keyword == "v") {
            read_vertex();
        } else if (keyword == "f") {
            read_face();
        } else if (std::find(kSkippedRecords.begin(), kSkippedRecords.end(), keyword) ==
                   kSkippedRecords.end()) {
            cursor_.fail("unknown OBJ record " + detail::quoted(keyword));
        }
    }

    void read_vertex() {
        Vec3 p;
        for (Eigen::Index axis = 0; axis < 3; ++axis)
            p[axis] = cursor_.double_in_line("vertex coordinate");
        for (int extra = 0;; ++extra) {
            const std::string_view token = cursor_.token_in_line();
            if (token.empty()) break;
            if (extra == kMaxExtraVertexValues) cursor_.fail("too many values in vertex record");
            cursor_.to_double(token, "vertex value");
        }
        if (soup_.points.size() == kNoIndex) cursor_.fail("more vertices than resharp indexes");
        soup_.points.push_back(p);
    }

    void read_face() {
        polygon_.clear();
        for (std::string_view corner = cursor_.token_in_line(); !corner.empty();
             corner = cursor_.token_in_line()) {
            polygon_.push_back(corner_vertex(corner));
        }
        if (polygon_.size() < 3) {
            cursor_.fail("face has " + std::to_string(polygon_.size()) +
                         " corners, at least 3 needed");
        }
        detail::append_fan(polygon_, soup_.triangles);
    }

    // "v", "v/vt", "v//vn" or "v/vt/vn": the vertex index; texture and normal indices are
    // checked for form only, since only positions are kept.
    Index corner_vertex(std::string_view corner) {
        const std::size_t slash = corner.find('/');
        const Index vertex = resolve(corner.substr(0, slash));
        if (slash == std::string_view::npos) return vertex;
        const std::string_view rest = corner.substr(slash + 1);
        const std::size_t second = rest.find('/');
        const std::string_view texture = rest.substr(0, second);
        if (second != std::string_view::npos) {
            const std::string_view normal = rest.substr(second + 1);
            if (normal.empty()) cursor_.fail("malformed face corner " + detail::quoted(corner));
            cursor_.to_integer(normal, "normal index");
        } else if (texture.empty()) {
            cursor_.fail("malformed face corner " + detail::quoted(corner));
        }
        if (!texture.empty()) cursor_.to_integer(texture, "texture index");
        return vertex;
    }

    // 1-based, or negative counting back from the last vertex read so far.
    Index resolve(std::string_view token) {
        const std::int64_t index = cursor_.to_integer(token, "vertex index");
        const auto count = static_cast<std::int64_t>(soup_.points.size());
        const std::int64_t zero_based = index < 0 ? count + index : index - 1;
        if (index == 0) cursor_.fail("vertex index 0 (OBJ indices start at 1)");
        if (zero_based < 0 || zero_based >= count) {
            cursor_.fail("vertex index " + std::to_string(index) + " out of range (" +
                         std::to_string(count) + " vertices defined so far)");
        }
        return static_cast<Index>(zero_based);
    }

    detail::TextCursor cursor_;
    TriangleSoup soup_;
    std::vector<Index> polygon_;
};

}  // namespace

TriangleSoup read_obj(std::string_view bytes, const std::string& name) {
    if (bytes.empty()) throw ParseError(name, FileLocation::line(1), "file is empty");
    return ObjReader(bytes, name).read();
}

TriangleSoup read_obj(std::istream& in, const std::string& name) {
    return read_obj(detail::read_stream_bytes(in, name), name);
}

void write_obj(std::ostream& out, const Mesh& mesh) {
    detail::require_writable(mesh);
    detail::OutputBuffer buffer(out);
    buffer.text("# written by resharp\n");
    for (const Vec3& p : mesh.positions) {
        buffer.text('v');
        for (Eigen::Index i = 0; i < 3; ++i) {
            buffer.text(' ');
            buffer.number(p[i]);
        }
        buffer.text('\n');
    }
    for (const Triangle& t : mesh.triangles) {
        buffer.text('f');
        for (const Index v : t) {
            buffer.text(' ');
            buffer.number(std::int64_t{v} + 1);
        }
        buffer.text('\n');
    }
}

}  // namespace resharp::io
