#include "resharp/io/ply.h"

#include <cmath>
#include <limits>

#include "resharp/core/errors.h"
#include "resharp/io/detail/byte_cursor.h"
#include "resharp/io/detail/file_bytes.h"
#include "resharp/io/detail/mesh_checks.h"
#include "resharp/io/detail/output_buffer.h"
#include "resharp/io/detail/ply_header.h"
#include "resharp/io/detail/reader_support.h"
#include "resharp/io/detail/text_cursor.h"

namespace resharp::io {
namespace {

using detail::PlyElementDecl;
using detail::PlyHeader;
using detail::PlyPropertyDecl;
using detail::PlyType;

bool in_range(PlyType type, std::int64_t value) {
    switch (type) {
        case PlyType::Int8:
            return value >= -128 && value <= 127;
        case PlyType::UInt8:
            return value >= 0 && value <= 255;
        case PlyType::Int16:
            return value >= -32768 && value <= 32767;
        case PlyType::UInt16:
            return value >= 0 && value <= 65535;
        case PlyType::Int32:
            return value >= INT32_MIN && value <= INT32_MAX;
        case PlyType::UInt32:
            return value >= 0 && value <= UINT32_MAX;
        default:
            return true;
    }
}

// Values of a binary body, bounds checked; failures name the byte offset of the bad value.
class BinarySource {
public:
    BinarySource(std::string_view bytes, const std::string& name, const PlyHeader& header)
        : cursor_(bytes, name, header.body_offset), order_(header.byte_order()) {}

    double value(PlyType type, std::string_view property) {
        mark_ = cursor_.offset();
        const double v = decode(type);
        if (!std::isfinite(v)) fail("property '" + std::string(property) + "' is NaN or infinite");
        return v;
    }

    void skip(std::uint64_t count, PlyType type) {
        mark_ = cursor_.offset();
        if (!detail::fits(count, detail::size_of(type), cursor_.remaining())) {
            fail("list of " + std::to_string(count) + " values runs past the end of the file");
        }
        cursor_.take(static_cast<std::size_t>(count * detail::size_of(type)), "a list");
    }

    void finish() const {
        if (cursor_.remaining() > 0) {
            cursor_.fail(std::to_string(cursor_.remaining()) +
                         " unexpected bytes after the last element");
        }
    }

    [[noreturn]] void fail(const std::string& reason) const { cursor_.fail_at(mark_, reason); }

private:
    template <class T>
    double get() {
        return static_cast<double>(cursor_.read<T>(order_, "a property value"));
    }

    double decode(PlyType type) {
        switch (type) {
            case PlyType::Int8:
                return get<std::int8_t>();
            case PlyType::UInt8:
                return get<std::uint8_t>();
            case PlyType::Int16:
                return get<std::int16_t>();
            case PlyType::UInt16:
                return get<std::uint16_t>();
            case PlyType::Int32:
                return get<std::int32_t>();
            case PlyType::UInt32:
                return get<std::uint32_t>();
            case PlyType::Float32:
                return get<float>();
            case PlyType::Float64:
                return get<double>();
        }
        return 0.0;
    }

    detail::ByteCursor cursor_;
    std::endian order_;
    std::size_t mark_ = 0;
};

// Values of an ASCII body, one token each; failures name the line.
class AsciiSource {
public:
    AsciiSource(std::string_view bytes, const std::string& name, const PlyHeader& header)
        : cursor_(bytes.substr(header.body_offset), name, '\0', header.body_line) {}

    double value(PlyType type, std::string_view property) {
        const std::string_view token = cursor_.token();
        if (token.empty()) {
            fail("missing value of property '" + std::string(property) +
                 "' (unexpected end of file)");
        }
        if (!detail::is_integer(type)) return cursor_.to_double(token, property);
        const std::int64_t v = cursor_.to_integer(token, property);
        if (!in_range(type, v)) {
            fail("value " + std::to_string(v) + " of property '" + std::string(property) +
                 "' out of range for " + detail::name_of(type));
        }
        return static_cast<double>(v);
    }

    void skip(std::uint64_t count, PlyType type) {
        for (std::uint64_t i = 0; i < count; ++i) value(type, "list item");
    }

    void finish() {
        if (!cursor_.only_space_left()) fail("unexpected data after the last element");
    }

    [[noreturn]] void fail(const std::string& reason) const { cursor_.fail(reason); }

private:
    detail::TextCursor cursor_;
};

template <class Source>
class BodyReader {
public:
    BodyReader(const PlyHeader& header, Source& source, bool keep_properties)
        : header_(header), source_(source), keep_properties_(keep_properties) {}

    PlyMesh read() {
        for (const PlyElementDecl& element : header_.elements) {
            if (element.properties.empty()) continue;  // no bytes to read, whatever the count
            if (element.name == "vertex") {
                read_vertices(element);
            } else if (element.name == "face") {
                read_faces(element);
            } else {
                skip_rows(element);
            }
        }
        source_.finish();
        return std::move(mesh_);
    }

private:
    std::uint64_t list_length(const PlyPropertyDecl& list) {
        const double n = source_.value(*list.list_count_type, list.name);
        if (n < 0) source_.fail("negative length of list '" + list.name + "'");
        return static_cast<std::uint64_t>(n);
    }

    // Where each vertex property goes: 0-2 an axis, 3+k the k-th kept property, -1 nowhere.
    std::vector<int> vertex_roles(const PlyElementDecl& element) {
        std::vector<int> roles;
        for (const PlyPropertyDecl& p : element.properties) {
            const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
            if (axis < 0 && keep_properties_ && !p.list_count_type) {
                roles.push_back(3 + static_cast<int>(mesh_.vertex_properties.size()));
                mesh_.vertex_properties.push_back({p.name, {}});
                mesh_.vertex_properties.back().values.reserve(element.count);
            } else {
                roles.push_back(axis);
            }
        }
        return roles;
    }

    void read_vertices(const PlyElementDecl& element) {
        const std::vector<int> roles = vertex_roles(element);
        mesh_.soup.points.reserve(element.count);
        for (std::uint64_t i = 0; i < element.count; ++i) {
            Vec3 p;
            for (std::size_t j = 0; j < roles.size(); ++j) {
                const PlyPropertyDecl& property = element.properties[j];
                if (property.list_count_type) {
                    source_.skip(list_length(property), property.type);
                    continue;
                }
                const double v = source_.value(property.type, property.name);
                if (roles[j] >= 3) {
                    mesh_.vertex_properties[roles[j] - 3].values.push_back(v);
                } else if (roles[j] >= 0) {
                    p[roles[j]] = v;
                }
            }
            mesh_.soup.points.push_back(p);
        }
    }

    void read_polygon(const PlyPropertyDecl& list, std::uint64_t vertex_count) {
        const std::uint64_t corners = list_length(list);
        if (corners < 3) {
            source_.fail("face has " + std::to_string(corners) + " corners, at least 3 needed");
        }
        polygon_.clear();
        for (std::uint64_t k = 0; k < corners; ++k) {
            const double index = source_.value(list.type, list.name);
            if (index < 0 || index >= static_cast<double>(vertex_count)) {
                source_.fail("vertex index " + std::to_string(static_cast<std::int64_t>(index)) +
                             " out of range (" + std::to_string(vertex_count) + " vertices)");
            }
            polygon_.push_back(static_cast<Index>(index));
        }
    }

    void read_faces(const PlyElementDecl& element) {
        const int list = detail::face_list_index(element);
        const std::size_t first_kept = mesh_.face_properties.size();
        for (std::size_t j = 0; j < element.properties.size(); ++j) {
            const PlyPropertyDecl& p = element.properties[j];
            if (keep_properties_ && !p.list_count_type)
                mesh_.face_properties.push_back({p.name, {}});
        }
        const std::uint64_t vertex_count = header_.elements[vertex_element()].count;
        mesh_.soup.triangles.reserve(element.count);
        std::vector<double> row;
        for (std::uint64_t i = 0; i < element.count; ++i) {
            row.clear();
            for (std::size_t j = 0; j < element.properties.size(); ++j) {
                const PlyPropertyDecl& property = element.properties[j];
                if (static_cast<int>(j) == list) {
                    read_polygon(property, vertex_count);
                } else if (property.list_count_type) {
                    source_.skip(list_length(property), property.type);
                } else {
                    const double v = source_.value(property.type, property.name);
                    if (keep_properties_) row.push_back(v);
                }
            }
            detail::append_fan(polygon_, mesh_.soup.triangles);
            for (std::size_t k = 0; k < row.size(); ++k) {
                auto& values = mesh_.face_properties[first_kept + k].values;
                values.insert(values.end(), polygon_.size() - 2, row[k]);
            }
        }
    }

    std::size_t vertex_element() const {
        for (std::size_t e = 0; e < header_.elements.size(); ++e) {
            if (header_.elements[e].name == "vertex") return e;
        }
        return 0;  // parse_ply_header guarantees one
    }

    void skip_rows(const PlyElementDecl& element) {
        for (std::uint64_t i = 0; i < element.count; ++i) {
            for (const PlyPropertyDecl& property : element.properties) {
                source_.skip(property.list_count_type ? list_length(property) : 1, property.type);
            }
        }
    }

    const PlyHeader& header_;
    Source& source_;
    bool keep_properties_;
    PlyMesh mesh_;
    std::vector<Index> polygon_;
};

PlyMesh read_any_ply(std::string_view bytes, const std::string& name, bool keep_properties) {
    if (bytes.empty()) throw ParseError(name, FileLocation::line(1), "file is empty");
    const PlyHeader header = detail::parse_ply_header(bytes, name);
    if (header.encoding == detail::PlyEncoding::Ascii) {
        AsciiSource source(bytes, name, header);
        return BodyReader<AsciiSource>(header, source, keep_properties).read();
    }
    BinarySource source(bytes, name, header);
    return BodyReader<BinarySource>(header, source, keep_properties).read();
}

const std::vector<double>* find_property(const std::vector<PlyProperty>& properties,
                                         std::string_view name) {
    for (const PlyProperty& p : properties) {
        if (p.name == name) return &p.values;
    }
    return nullptr;
}

// One row of values in the ASCII encoding: separated by spaces, ended by a newline.
class AsciiRows {
public:
    explicit AsciiRows(detail::OutputBuffer& out) : out_(out) {}
    void put(double v) {
        separate();
        out_.number(v);
    }
    template <class Int>
    void put(Int v) {
        separate();
        out_.number(std::int64_t{v});
    }
    void end_row() {
        out_.text('\n');
        first_ = true;
    }

private:
    void separate() {
        if (!first_) out_.text(' ');
        first_ = false;
    }
    detail::OutputBuffer& out_;
    bool first_ = true;
};

// The binary little-endian encoding: values back to back.
class BinaryRows {
public:
    explicit BinaryRows(detail::OutputBuffer& out) : out_(out) {}
    template <class T>
    void put(T v) {
        out_.binary(v);
    }
    void end_row() {}

private:
    detail::OutputBuffer& out_;
};

void put_rgb(auto& rows, const Rgb& c) {
    rows.put(c.red);
    rows.put(c.green);
    rows.put(c.blue);
}

void write_header(detail::OutputBuffer& out, const Mesh& mesh, Encoding encoding,
                  const MeshAttributes& attributes) {
    out.text(encoding == Encoding::Binary ? "ply\nformat binary_little_endian 1.0\n"
                                          : "ply\nformat ascii 1.0\n");
    out.text("comment written by resharp\nelement vertex ");
    out.number(static_cast<std::int64_t>(mesh.vertex_count()));
    out.text("\nproperty double x\nproperty double y\nproperty double z\n");
    if (!attributes.vertex_normals.empty()) {
        out.text("property double nx\nproperty double ny\nproperty double nz\n");
    }
    if (!attributes.vertex_surfaces.empty()) out.text("property int surface\n");
    if (!attributes.vertex_surface_points.empty()) {
        out.text("property double sx\nproperty double sy\nproperty double sz\n");
    }
    constexpr const char* kRgb = "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (!attributes.vertex_colors.empty()) out.text(kRgb);
    out.text("element face ");
    out.number(static_cast<std::int64_t>(mesh.face_count()));
    out.text("\nproperty list uchar int vertex_indices\n");
    if (!attributes.face_colors.empty()) out.text(kRgb);
    out.text("end_header\n");
}

template <class Rows>
void write_body(Rows& rows, const Mesh& mesh, const MeshAttributes& attributes) {
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        for (Eigen::Index i = 0; i < 3; ++i) rows.put(mesh.positions[v][i]);
        if (!attributes.vertex_normals.empty()) {
            for (Eigen::Index i = 0; i < 3; ++i) rows.put(attributes.vertex_normals[v][i]);
        }
        if (!attributes.vertex_surfaces.empty()) rows.put(attributes.vertex_surfaces[v]);
        if (!attributes.vertex_surface_points.empty()) {
            for (Eigen::Index i = 0; i < 3; ++i) rows.put(attributes.vertex_surface_points[v][i]);
        }
        if (!attributes.vertex_colors.empty()) put_rgb(rows, attributes.vertex_colors[v]);
        rows.end_row();
    }
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        rows.put(std::uint8_t{3});
        for (const Index v : mesh.triangles[f]) rows.put(static_cast<std::int32_t>(v));
        if (!attributes.face_colors.empty()) put_rgb(rows, attributes.face_colors[f]);
        rows.end_row();
    }
}

}  // namespace

const std::vector<double>* PlyMesh::vertex_property(std::string_view name) const {
    return find_property(vertex_properties, name);
}

const std::vector<double>* PlyMesh::face_property(std::string_view name) const {
    return find_property(face_properties, name);
}

TriangleSoup read_ply(std::string_view bytes, const std::string& name) {
    return read_any_ply(bytes, name, false).soup;
}

TriangleSoup read_ply(std::istream& in, const std::string& name) {
    return read_ply(detail::read_stream_bytes(in, name), name);
}

PlyMesh read_ply_with_properties(std::string_view bytes, const std::string& name) {
    return read_any_ply(bytes, name, true);
}

PlyMesh read_ply_with_properties(const std::filesystem::path& path) {
    return read_ply_with_properties(detail::read_file_bytes(path), path.string());
}

void write_ply(std::ostream& out, const Mesh& mesh, Encoding encoding,
               const MeshAttributes& attributes) {
    detail::require_writable(mesh, attributes);
    if (mesh.vertex_count() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
        throw InvalidInput("PLY int vertex indices cannot address " +
                           std::to_string(mesh.vertex_count()) + " vertices");
    }
    detail::OutputBuffer buffer(out);
    write_header(buffer, mesh, encoding, attributes);
    if (encoding == Encoding::Binary) {
        BinaryRows rows(buffer);
        write_body(rows, mesh, attributes);
    } else {
        AsciiRows rows(buffer);
        write_body(rows, mesh, attributes);
    }
}

}  // namespace resharp::io
