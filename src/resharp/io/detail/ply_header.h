#pragma once
/// Internal to resharp::io: the PLY header, parsed and checked against the file size before the
/// body is touched.

#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace resharp::io::detail {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t size_of(PlyType type);
bool is_integer(PlyType type);
/// The name used in messages ("uchar", "float", ...).
const char* name_of(PlyType type);

struct PlyPropertyDecl {
    std::string name;
    PlyType type = PlyType::Float32;         ///< the value type, or the item type of a list
    std::optional<PlyType> list_count_type;  ///< set for `property list COUNT ITEM NAME`
};

struct PlyElementDecl {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyPropertyDecl> properties;
    std::uint64_t line = 0;  ///< where the header declares it, for messages

    /// Index of the property called `name`, or -1.
    int find(std::string_view property) const;
};

/// Index of the face element's vertex index list (`vertex_indices`, or `vertex_index`), or -1.
int face_list_index(const PlyElementDecl& face);

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElementDecl> elements;
    std::size_t body_offset = 0;  ///< first byte after "end_header\n"
    std::uint64_t body_line = 0;  ///< line number of that byte

    std::endian byte_order() const {
        return encoding == PlyEncoding::BinaryBigEndian ? std::endian::big : std::endian::little;
    }
};

/// Parses and checks the header of the PLY file `bytes`: the syntax, a vertex element with
/// scalar x, y, z, a face element with an integer vertex_indices (or vertex_index) list, and
/// element counts the body is large enough to hold.
/// \throws ParseError naming `name` and the header line.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& name);

}  // namespace resharp::io::detail
