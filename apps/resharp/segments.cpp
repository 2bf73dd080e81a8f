#include "segments.h"

#include <cmath>

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
            colors.face.push_back(kCornerTriangleColor);
        else if (layers.face_role[f] == BandRole::Edge)
            colors.face.push_back(kEdgeTriangleColor);
        else
            colors.face.push_back(layers.patch_color[f]);
    }
    return colors;
}

SegmentLayers layers_from_colors(std::span<const io::Rgb> vertex, std::span<const io::Rgb> face) {
    SegmentLayers layers;
    layers.is_edge_vertex.reserve(vertex.size());
    for (const io::Rgb& c : vertex) layers.is_edge_vertex.push_back(c == kEdgeVertexColor);
    layers.face_role.reserve(face.size());
    layers.patch_color.reserve(face.size());
    for (const io::Rgb& c : face) {
        const BandRole role = c == kCornerTriangleColor ? BandRole::Corner
                              : c == kEdgeTriangleColor ? BandRole::Edge
                                                        : BandRole::None;
        layers.face_role.push_back(role);
        layers.patch_color.push_back(role == BandRole::None ? c : kBandFace);
    }
    return layers;
}

}  // namespace resharp::cli
