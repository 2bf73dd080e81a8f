#pragma once
/// Colours for `resharp restore --segments` and the viewer: what each segmentation found.

#include <span>
#include <vector>

#include "resharp/io/attributes.h"
#include "resharp/pipeline/restore.h"

namespace resharp::cli {

/// The highlight colours, shared by the PLY file and the viewer page.
inline constexpr io::Rgb kEdgeVertexColor{220, 40, 30};
inline constexpr io::Rgb kPlainVertexColor{200, 200, 200};
inline constexpr io::Rgb kEdgeTriangleColor{255, 210, 0};
inline constexpr io::Rgb kCornerTriangleColor{230, 0, 230};

/// What the segmentation found on the input's elements, one layer per thing a viewer toggles.
struct SegmentLayers {
    std::vector<std::uint8_t> is_edge_vertex;  ///< #V: 1 for edge vertices (paper §3)
    std::vector<BandRole> face_role;           ///< #F: edge or corner triangle, or neither
    std::vector<io::Rgb> patch_color;          ///< #F: a muted colour per feature patch, dark
                                               ///< grey for band faces outside every patch
};

struct SegmentColors {
    std::vector<io::Rgb> vertex;  ///< #V: edge vertices red, others light grey
    std::vector<io::Rgb> face;    ///< #F: a colour per feature patch; edge triangles yellow,
                                  ///< corner triangles magenta, other band faces dark grey
};

SegmentLayers segment_layers(const Segmentation& segmentation);

/// The layers as one colour per element (the PLY file of --segments).
SegmentColors color_segments(const SegmentLayers& layers);

/// The layers back from the colours of a --segments file: edge vertices, edge and corner
/// triangles by their highlight colour, every other face colour taken as its patch's.
/// Takes #V vertex and #F face colours; gives layers of the same sizes.
SegmentLayers layers_from_colors(std::span<const io::Rgb> vertex, std::span<const io::Rgb> face);

}  // namespace resharp::cli
