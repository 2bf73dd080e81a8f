#include "segments.h"

#include <cmath>

#include "resharp/eval/evaluation_files.h"

namespace resharp::cli {
namespace {

constexpr io::Rgb kEdgeVertex{220, 40, 30};
constexpr io::Rgb kPlainVertex{200, 200, 200};
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

SegmentColors color_segments(const Segmentation& s) {
    SegmentColors colors;
    colors.vertex.reserve(s.is_edge_vertex.size());
    for (std::uint8_t edge : s.is_edge_vertex)
        colors.vertex.push_back(edge ? kEdgeVertex : kPlainVertex);
    colors.face.reserve(s.face_patch.size());
    for (std::size_t f = 0; f < s.face_patch.size(); ++f) {
        if (s.face_role[f] == BandRole::Corner)
            colors.face.push_back(eval::kCornerTriangleColor);
        else if (s.face_role[f] == BandRole::Edge)
            colors.face.push_back(eval::kEdgeTriangleColor);
        else if (s.face_patch[f] == kNoIndex)
            colors.face.push_back(kBandFace);
        else
            colors.face.push_back(patch_color(s.face_patch[f]));
    }
    return colors;
}

}  // namespace resharp::cli
