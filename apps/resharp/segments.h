#pragma once
/// Colours for `resharp restore --segments`: what each segmentation found, for a PLY viewer.

#include <vector>

#include "resharp/io/attributes.h"
#include "resharp/pipeline/restore.h"

namespace resharp::cli {

struct SegmentColors {
    std::vector<io::Rgb> vertex;  ///< #V: edge vertices red, others light grey
    std::vector<io::Rgb> face;    ///< #F: a colour per feature patch; edge triangles yellow,
                                  ///< corner triangles magenta, other band faces dark grey
};

SegmentColors color_segments(const Segmentation& segmentation);

}  // namespace resharp::cli
