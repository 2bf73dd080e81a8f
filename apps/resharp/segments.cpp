#include "segments.h"

#include <cmath>
#include <string>

#include "resharp/core/errors.h"
#include "resharp/io/ply.h"

namespace resharp::cli {
namespace {

constexpr io::Rgb kBandFace{80, 80, 80};

/// Distinct muted colours by walking the hue circle in golden-angle steps; saturation and value
/// stay below the highlight colours so detections stand out.
io::Rgb patch_color(Index patch) {
    const double hue = std::fmod(static_cast<double>(patch) * 137.508, 360.0) / 60.0;
    const double s = 0.45, v = 0.85;
    const double c = v * s;
    const double x = c * (1.0 - std::abs(std::fmod(hue, 2.0) - 1.0));
    double r = 0, g = 0, b = 0;
    switch (static_cast<int>(hue)) {
        case 0:
            r = c;
            g = x;
            break;
        case 1:
            r = x;
            g = c;
            break;
        case 2:
            g = c;
            b = x;
            break;
        case 3:
            g = x;
            b = c;
            break;
        case 4:
            r = x;
            b = c;
            break;
        default:
            r = c;
            b = x;
            break;
    }
    auto channel = [&](double value) {
        return static_cast<std::uint8_t>(std::lround(255.0 * (value + v - c)));
    };
    return {channel(r), channel(g), channel(b)};
}

/// The colours of one element kind of a --segments file, which must be one per element.
std::vector<io::Rgb> colors_of(const io::PlyMesh& ply, bool is_vertex, std::size_t count,
                               const std::string& path) {
    const char* what = is_vertex ? "vertex" : "face";
    auto channel = [&](const char* name) {
        const auto* values = is_vertex ? ply.vertex_property(name) : ply.face_property(name);
        if (values == nullptr) {
            throw ReadError(path, std::string("no ") + what +
                                      " colours: not a file written by resharp restore --segments");
        }
        if (values->size() != count) {
            throw ReadError(path, std::to_string(values->size()) + " " + what +
                                      " colours for the " + std::to_string(count) + " " + what +
                                      "s of the input: segments of another mesh");
        }
        return values;
    };
    const auto *red = channel("red"), *green = channel("green"), *blue = channel("blue");
    std::vector<io::Rgb> colors(count);
    for (std::size_t i = 0; i < count; ++i) {
        colors[i] = {static_cast<std::uint8_t>((*red)[i]), static_cast<std::uint8_t>((*green)[i]),
                     static_cast<std::uint8_t>((*blue)[i])};
    }
    return colors;
}

}  // namespace

SegmentLayers segment_layers(const Segmentation& s) {
    SegmentLayers layers{.is_edge_vertex = s.is_edge_vertex, .face_role = s.face_role};
    layers.patch_color.reserve(s.face_patch.size());
    for (Index patch : s.face_patch)
        layers.patch_color.push_back(patch == kNoIndex ? kBandFace : patch_color(patch));
    return layers;
}

SegmentColors color_segments(const SegmentLayers& layers) {
    SegmentColors colors;
    colors.vertex.reserve(layers.is_edge_vertex.size());
    for (std::uint8_t edge : layers.is_edge_vertex)
        colors.vertex.push_back(edge ? kEdgeVertexColor : kPlainVertexColor);
    colors.face.reserve(layers.face_role.size());
    for (std::size_t f = 0; f < layers.face_role.size(); ++f) {
        if (layers.face_role[f] == BandRole::Corner)
            colors.face.push_back(eval::kCornerTriangleColor);
        else if (layers.face_role[f] == BandRole::Edge)
            colors.face.push_back(eval::kEdgeTriangleColor);
        else
            colors.face.push_back(layers.patch_color[f]);
    }
    return colors;
}

SegmentLayers read_segment_layers(const std::filesystem::path& path, const Mesh& input) {
    const io::PlyMesh ply = io::read_ply_with_properties(path);
    const std::vector<io::Rgb> vertex = colors_of(ply, true, input.vertex_count(), path.string());
    const std::vector<io::Rgb> face = colors_of(ply, false, input.face_count(), path.string());
    SegmentLayers layers{.face_role = eval::decode_segment_roles(ply, path.string(), face.size())};
    for (const io::Rgb& c : vertex) layers.is_edge_vertex.push_back(c == kEdgeVertexColor);
    for (std::size_t f = 0; f < face.size(); ++f)
        layers.patch_color.push_back(layers.face_role[f] == BandRole::None ? face[f] : kBandFace);
    return layers;
}

}  // namespace resharp::cli
