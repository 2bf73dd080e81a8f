#include "page.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <string_view>

#include "assets.h"
#include "resharp/core/errors.h"
#include "resharp/eval/position_index.h"
#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"

namespace resharp::viewer {
namespace {

using Bytes = std::vector<std::uint8_t>;

/// Per restored vertex (#V restored): 1 where its position is no input vertex's, to float
/// precision. By position, not by index, so that a restored mesh read back from a file (STL
/// keeps no vertex order, and only floats) works as well as restore()'s own result.
std::vector<std::uint8_t> new_points(const Mesh& input, const Mesh& restored) {
    const eval::PositionIndex index(input.positions);
    std::vector<std::uint8_t> is_new(restored.vertex_count());
    for (std::size_t v = 0; v < is_new.size(); ++v)
        is_new[v] = !index.find(restored.positions[v]).has_value();
    return is_new;
}

/// How many leading vertices of `restored` equal the input's (all input vertices after
/// restore(), which keeps them first): the page stores those positions once.
std::size_t shared_prefix(const Mesh& input, const Mesh& restored) {
    const std::size_t n = std::min(input.vertex_count(), restored.vertex_count());
    std::size_t shared = 0;
    while (shared < n && input.positions[shared] == restored.positions[shared]) ++shared;
    return shared;
}

// Typed arrays on the page are read little-endian whatever the machine writing the page.
void put_u32(Bytes& bytes, std::uint32_t word) {
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back((word >> shift) & 0xffu);
}

Bytes float_bytes(std::span<const Vec3> positions) {
    Bytes bytes;
    bytes.reserve(positions.size() * 12);
    for (const Vec3& p : positions) {
        for (int k = 0; k < 3; ++k) put_u32(bytes, std::bit_cast<std::uint32_t>(float(p[k])));
    }
    return bytes;
}

template <std::size_t N>
Bytes index_bytes(std::span<const std::array<Index, N>> tuples) {
    Bytes bytes;
    bytes.reserve(tuples.size() * N * 4);
    for (const auto& tuple : tuples) {
        for (Index i : tuple) put_u32(bytes, i);
    }
    return bytes;
}

Bytes rgb_bytes(std::span<const io::Rgb> colors) {
    Bytes bytes;
    bytes.reserve(colors.size() * 3);
    for (const io::Rgb& c : colors) bytes.insert(bytes.end(), {c.red, c.green, c.blue});
    return bytes;
}

Bytes role_bytes(std::span<const BandRole> roles) {
    Bytes bytes;
    bytes.reserve(roles.size());
    for (BandRole role : roles) bytes.push_back(static_cast<std::uint8_t>(role));
    return bytes;
}

void write_base64(std::ostream& out, std::span<const std::uint8_t> bytes) {
    constexpr std::string_view kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const std::uint32_t word = bytes[i] << 16 | bytes[i + 1] << 8 | bytes[i + 2];
        for (int shift = 18; shift >= 0; shift -= 6)
            text.push_back(kAlphabet[(word >> shift) & 63]);
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        const std::uint32_t word = bytes[i] << 16 | (rest == 2 ? bytes[i + 1] << 8 : 0);
        text.push_back(kAlphabet[word >> 18]);
        text.push_back(kAlphabet[(word >> 12) & 63]);
        text.push_back(rest == 2 ? kAlphabet[(word >> 6) & 63] : '=');
        text.push_back('=');
    }
    out << text;
}

void write_block(std::ostream& out, std::string_view id, std::span<const std::uint8_t> bytes) {
    out << "<script type=\"application/octet-stream;base64\" id=\"" << id << "\">";
    write_base64(out, bytes);
    out << "</script>\n";
}

std::string escape_html(std::string_view text) {
    std::string escaped;
    for (char c : text) {
        switch (c) {
            case '&':
                escaped += "&amp;";
                break;
            case '<':
                escaped += "&lt;";
                break;
            case '>':
                escaped += "&gt;";
                break;
            case '"':
                escaped += "&quot;";
                break;
            default:
                escaped += c;
        }
    }
    return escaped;
}

nlohmann::json rgb_json(const io::Rgb& c) { return {c.red, c.green, c.blue}; }

/// The JSON block #resharp-meta. "</" is written "<\/" (the same JSON string) so that no text
/// in it can close the script element.
std::string meta_json(const PageContent& content, std::size_t shared) {
    const nlohmann::json meta{
        {"title", content.title},
        {"numbers", content.numbers},
        {"segments", content.segments != nullptr},
        {"colors",
         {{"edge_vertex", rgb_json(cli::kEdgeVertexColor)},
          {"edge_triangle", rgb_json(eval::kEdgeTriangleColor)},
          {"corner_triangle", rgb_json(eval::kCornerTriangleColor)}}},
        {"input",
         {{"vertices", content.input->vertex_count()}, {"triangles", content.input->face_count()}}},
        {"restored",
         {{"vertices", content.restored->vertex_count()},
          {"triangles", content.restored->face_count()},
          {"shared_vertices", shared}}},
    };
    std::string text = meta.dump();
    for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
        text.replace(at, 2, "<\\/");
    return text;
}

void write_data(std::ostream& out, const PageContent& content) {
    const Mesh& input = *content.input;
    const Mesh& restored = *content.restored;
    const std::size_t shared = shared_prefix(input, restored);
    out << "<script type=\"application/json\" id=\"resharp-meta\">" << meta_json(content, shared)
        << "</script>\n";
    write_block(out, "input-positions", float_bytes(input.positions));
    write_block(out, "input-triangles", index_bytes<3>(input.triangles));
    write_block(out, "restored-positions",
                float_bytes(std::span(restored.positions).subspan(shared)));
    write_block(out, "restored-triangles", index_bytes<3>(restored.triangles));
    write_block(out, "sharp-edges", index_bytes<2>(sharp_edges(input, restored)));
    if (const cli::SegmentLayers* s = content.segments) {
        write_block(out, "segment-edge-vertices", s->is_edge_vertex);
        write_block(out, "segment-roles", role_bytes(s->face_role));
        write_block(out, "segment-patches", rgb_bytes(s->patch_color));
    }
}

void check(const PageContent& content) {
    if (content.input == nullptr || content.restored == nullptr)
        throw InvalidInput("viewer page: both the input and the restored mesh are needed");
    if (const cli::SegmentLayers* s = content.segments) {
        if (s->is_edge_vertex.size() != content.input->vertex_count() ||
            s->face_role.size() != content.input->face_count() ||
            s->patch_color.size() != content.input->face_count()) {
            throw InvalidInput("viewer page: the segments do not match the input mesh (" +
                               std::to_string(s->is_edge_vertex.size()) + " vertices and " +
                               std::to_string(s->face_role.size()) + " faces for " +
                               std::to_string(content.input->vertex_count()) + " and " +
                               std::to_string(content.input->face_count()) + ")");
        }
    }
}

}  // namespace

std::vector<std::array<Index, 2>> sharp_edges(const Mesh& input, const Mesh& restored,
                                              double min_dihedral_deg) {
    const std::vector<std::uint8_t> is_new = new_points(input, restored);
    const Connectivity connectivity = build_connectivity(restored);
    const std::vector<Vec3> normals = face_normals(restored);
    std::vector<std::array<Index, 2>> edges;
    for (Index h = 0; h < connectivity.twin.size(); ++h) {
        const Index twin = connectivity.twin[h];
        if (twin == kNoIndex || twin < h) continue;  // each manifold edge once
        const Index a = tail_vertex(restored, h), b = head_vertex(restored, h);
        if (!is_new[a] && !is_new[b]) continue;
        if (angle_deg(normals[face_of(h)], normals[face_of(twin)]) > min_dihedral_deg)
            edges.push_back({a, b});
    }
    return edges;
}

void write_page(std::ostream& out, const PageContent& content) {
    check(content);
    // Copy the template, putting each part in place of its marker.
    const std::string_view markers[] = {"@TITLE@", "@DATA@", "@SCRIPT@", "@LICENSE@"};
    std::string_view rest = kTemplate;
    while (!rest.empty()) {
        const std::size_t at = rest.find('@');
        out << rest.substr(0, at);
        if (at == std::string_view::npos) break;
        rest.remove_prefix(at);
        const auto* marker = std::find_if(std::begin(markers), std::end(markers),
                                          [&](std::string_view m) { return rest.starts_with(m); });
        if (marker == std::end(markers)) {
            out << '@';
            rest.remove_prefix(1);
            continue;
        }
        rest.remove_prefix(marker->size());
        if (*marker == "@TITLE@") out << escape_html(content.title);
        if (*marker == "@DATA@") write_data(out, content);
        if (*marker == "@SCRIPT@") out << kScript;
        if (*marker == "@LICENSE@") out << kLicense;
    }
}

}  // namespace resharp::viewer
