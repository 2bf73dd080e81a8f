#pragma once
/// Colours for `resharp restore --segments` and the viewer: what each segmentation found.

#include <filesystem>
#include <vector>

#include "resharp/eval/evaluation_files.h"  // the edge and corner triangle colours
#include "resharp/io/attributes.h"
#include "resharp/pipeline/restore.h"

namespace resharp::cli {

/// The vertex colours, shared by the PLY file and the viewer page. Edge and corner triangles
/// are eval::kEdgeTriangleColor and eval::kCornerTriangleColor, which `evaluate` reads back.
inline constexpr io::Rgb kEdgeVertexColor{220, 40, 30};
inline constexpr io::Rgb kPlainVertexColor{200, 200, 200};

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

/// The layers of the --segments file at `path` written for `input` (the welded input itself,
/// so its #V vertices and #F faces are the input's, in order): edge vertices and edge and
/// corner triangles by their highlight colours, every other face colour taken as its patch's.
/// \throws ReadError naming the file if it cannot be read or has no colours, or its counts are
/// not the input's (segments of another mesh); ParseError as read_ply_with_properties.
SegmentLayers read_segment_layers(const std::filesystem::path& path, const Mesh& input);

}  // namespace resharp::cli
