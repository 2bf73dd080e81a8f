#include "resharp/io/detail/ply_header.h"

#include <algorithm>
#include <array>
#include <limits>

#include "resharp/core/errors.h"
#include "resharp/io/detail/reader_support.h"
#include "resharp/io/detail/text_cursor.h"

namespace resharp::io::detail {
namespace {

struct TypeName {
    std::string_view name;
    PlyType type;
};

constexpr std::array<TypeName, 16> kTypeNames = {{
    {"char", PlyType::Int8},
    {"int8", PlyType::Int8},
    {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},
    {"short", PlyType::Int16},
    {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},
    {"uint16", PlyType::UInt16},
    {"int", PlyType::Int32},
    {"int32", PlyType::Int32},
    {"uint", PlyType::UInt32},
    {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},
    {"float32", PlyType::Float32},
    {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
}};

class HeaderParser {
public:
    HeaderParser(std::string_view bytes, const std::string& name)
        : bytes_(bytes), cursor_(bytes, name) {}

    PlyHeader parse() {
        if (cursor_.token_in_line() != "ply")
            cursor_.fail("not a PLY file: expected 'ply' on line 1");
        end_line();
        bool has_format = false;
        for (;;) {
            if (!cursor_.next_line()) cursor_.fail("missing 'end_header' (unexpected end of file)");
            const std::string_view keyword = cursor_.token_in_line();
            if (keyword == "end_header") break;
            if (keyword == "format") {
                read_format();
                has_format = true;
            } else if (keyword == "element") {
                read_element();
            } else if (keyword == "property") {
                read_property();
            } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
                cursor_.fail("unknown header keyword " + quoted(keyword));
            }
        }
        end_line();
        if (!has_format) cursor_.fail("header has no 'format' line");
        check_elements();
        cursor_.next_line();
        header_.body_offset = cursor_.offset();
        header_.body_line = cursor_.line();
        check_counts();
        return std::move(header_);
    }

private:
    void end_line() {
        if (const std::string_view extra = cursor_.token_in_line(); !extra.empty()) {
            cursor_.fail("unexpected " + quoted(extra) + " at the end of the header line");
        }
    }

    std::string_view word(const char* what) {
        const std::string_view token = cursor_.token_in_line();
        if (token.empty()) cursor_.fail(std::string("missing ") + what);
        return token;
    }

    PlyType type(const char* what) { return type_named(word(what)); }

    void read_format() {
        const std::string_view encoding = word("format");
        if (encoding == "ascii") {
            header_.encoding = PlyEncoding::Ascii;
        } else if (encoding == "binary_little_endian") {
            header_.encoding = PlyEncoding::BinaryLittleEndian;
        } else if (encoding == "binary_big_endian") {
            header_.encoding = PlyEncoding::BinaryBigEndian;
        } else {
            cursor_.fail("unknown PLY format " + quoted(encoding));
        }
        if (const std::string_view version = word("format version"); version != "1.0") {
            cursor_.fail("unsupported PLY version " + quoted(version));
        }
        end_line();
    }

    void read_element() {
        PlyElementDecl element;
        element.name = word("element name");
        if (this->element(element.name) != nullptr) {
            cursor_.fail("element " + quoted(element.name) + " declared twice");
        }
        element.line = cursor_.line();
        const std::int64_t count = cursor_.to_integer(word("element count"), "element count");
        if (count < 0) cursor_.fail("negative element count");
        element.count = static_cast<std::uint64_t>(count);
        end_line();
        header_.elements.push_back(std::move(element));
    }

    void read_property() {
        if (header_.elements.empty()) cursor_.fail("property before any element");
        PlyPropertyDecl property;
        const std::string_view first = word("property type");
        if (first == "list") {
            property.list_count_type = type("list count type");
            if (!is_integer(*property.list_count_type))
                cursor_.fail("list count type must be an integer");
            property.type = type("list item type");
        } else {
            property.type = type_named(first);
        }
        property.name = word("property name");
        end_line();
        PlyElementDecl& element = header_.elements.back();
        if (element.find(property.name) >= 0) {
            cursor_.fail("property " + quoted(property.name) + " declared twice");
        }
        element.properties.push_back(std::move(property));
    }

    PlyType type_named(std::string_view token) const {
        for (const TypeName& t : kTypeNames) {
            if (t.name == token) return t.type;
        }
        cursor_.fail("unknown PLY type " + quoted(token));
    }

    const PlyElementDecl* element(std::string_view element_name) {
        for (const PlyElementDecl& e : header_.elements) {
            if (e.name == element_name) return &e;
        }
        return nullptr;
    }

    void check_elements() {
        const PlyElementDecl* vertex = element("vertex");
        if (vertex == nullptr) cursor_.fail("header declares no 'vertex' element");
        for (const char* axis : {"x", "y", "z"}) {
            const int p = vertex->find(axis);
            if (p < 0 || vertex->properties[p].list_count_type) {
                cursor_.fail(std::string("vertex element has no scalar '") + axis + "' property");
            }
        }
        if (vertex->count > std::numeric_limits<std::uint32_t>::max()) {
            cursor_.fail("more vertices than resharp indexes (2^32 - 1)");
        }
        const PlyElementDecl* face = element("face");
        if (face == nullptr) cursor_.fail("header declares no 'face' element");
        const int list = face_list_index(*face);
        if (list < 0 || !face->properties[list].list_count_type ||
            !is_integer(face->properties[list].type)) {
            cursor_.fail("face element has no integer 'vertex_indices' list");
        }
        if (face->count == 0) cursor_.fail("PLY holds no faces");
    }

    // Each element needs at least this many bytes per row: binary, the scalars and list counts;
    // ASCII, one digit and one separator per value.
    std::uint64_t min_row_bytes(const PlyElementDecl& element) const {
        std::uint64_t bytes = 0;
        for (const PlyPropertyDecl& p : element.properties) {
            bytes += header_.encoding == PlyEncoding::Ascii
                         ? 2
                         : size_of(p.list_count_type.value_or(p.type));
        }
        return bytes;
    }

    void check_counts() {
        std::uint64_t left = bytes_.size() - header_.body_offset;
        for (const PlyElementDecl& element : header_.elements) {
            const std::uint64_t row = min_row_bytes(element);
            if (!fits(element.count, row, left + (header_.encoding == PlyEncoding::Ascii))) {
                throw_count_error(element, row, left);
            }
            left -= std::min(left, element.count * row);
        }
    }

    [[noreturn]] void throw_count_error(const PlyElementDecl& e, std::uint64_t row,
                                        std::uint64_t left) const {
        throw ParseError(cursor_.name(), FileLocation::line(e.line),
                         "element '" + e.name + "' promises " + std::to_string(e.count) +
                             " rows of at least " + std::to_string(row) + " bytes, but only " +
                             std::to_string(left) + " bytes are left (file truncated?)");
    }

    std::string_view bytes_;
    TextCursor cursor_;
    PlyHeader header_;
};

}  // namespace

std::size_t size_of(PlyType type) {
    switch (type) {
        case PlyType::Int8:
        case PlyType::UInt8:
            return 1;
        case PlyType::Int16:
        case PlyType::UInt16:
            return 2;
        case PlyType::Int32:
        case PlyType::UInt32:
        case PlyType::Float32:
            return 4;
        case PlyType::Float64:
            return 8;
    }
    return 8;
}

bool is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

const char* name_of(PlyType type) {
    for (const TypeName& t : kTypeNames) {
        if (t.type == type) return t.name.data();
    }
    return "?";
}

int PlyElementDecl::find(std::string_view property) const {
    for (std::size_t i = 0; i < properties.size(); ++i) {
        if (properties[i].name == property) return static_cast<int>(i);
    }
    return -1;
}

int face_list_index(const PlyElementDecl& face) {
    const int indices = face.find("vertex_indices");
    return indices >= 0 ? indices : face.find("vertex_index");
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name) {
    return HeaderParser(bytes, name).parse();
}

}  // namespace resharp::io::detail
