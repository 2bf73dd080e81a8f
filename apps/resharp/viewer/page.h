#pragma once
/// The self-contained HTML page of `resharp view` and `resharp restore --html`: the input and
/// the restored mesh side by side under one camera (orbit, zoom, pan), the restored sharp edges
/// drawn as lines, the detected segmentation as colours to toggle, a wireframe toggle, and the
/// report's numbers. three.js is inlined and the meshes are inlined as base64 of typed arrays,
/// so the page opens with no network.

#include <array>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "resharp/mesh/mesh.h"
#include "segments.h"

namespace resharp::viewer {

struct PageContent {
    std::string title;                             ///< shown in the header and the window title
    const Mesh* input = nullptr;                   ///< the mesh as it went in (required)
    const Mesh* restored = nullptr;                ///< the restored mesh (required)
    const cli::SegmentLayers* segments = nullptr;  ///< on `input`'s elements, or null
    nlohmann::json numbers = nlohmann::json::object();  ///< shown as a table, nested by section
};

/// The restored sharp edges to draw: edges of `restored` with at least one end at a new point
/// (a position that is no vertex of `input`, to float precision) whose two faces meet at more than
/// `min_dihedral_deg`. That is the chain through the inserted points, without the edges that fan
/// out from each point into the faces it split (those lie flat). Gives vertex pairs of
/// `restored`, each edge once, in order of its first half-edge.
std::vector<std::array<Index, 2>> sharp_edges(const Mesh& input, const Mesh& restored,
                                              double min_dihedral_deg = 20.0);

/// Writes the page to `out` (check its state afterwards). Positions are stored as 32-bit floats;
/// the restored mesh's leading vertices that equal the input's are stored once.
/// \throws InvalidInput if a mesh is missing or the segments' sizes do not match `input`.
void write_page(std::ostream& out, const PageContent& content);

}  // namespace resharp::viewer
