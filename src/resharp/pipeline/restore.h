#pragma once
/// The one entry point: the whole method of the paper on an indexed triangle mesh.

#include <cstdint>
#include <vector>

#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/options.h"
#include "resharp/pipeline/report.h"
#include "resharp/restoration/band_classification.h"

namespace resharp {

/// What both segmentations found, on the input mesh's elements.
struct Segmentation {
    std::vector<std::uint8_t> is_edge_vertex;  ///< per input vertex (#V): edge-based result, §3
    std::vector<Index> vertex_patch;  ///< per input vertex (#V): feature patch, or kNoIndex
    std::vector<Index> face_patch;    ///< per input face (#F): feature patch, kNoIndex in bands
    std::vector<BandRole> face_role;  ///< per input face (#F): edge or corner triangle
};

struct RestoreResult {
    /// The restored mesh: the input vertices first, unchanged and in order, then the new points
    /// on sharp edges and corners; faces in input order, each unchanged or replaced in place by
    /// its pieces.
    Mesh mesh;
    /// Per output face (#F out): the input face it is or was cut from, so that callers can
    /// carry face attributes (tool ids, colours) over.
    std::vector<Index> source_face;
    RestoreReport report;
    /// Filled only when RestoreOptions::keep_segmentation is set.
    Segmentation segmentation;
};

/// Paper §3-§5: finds the chamfer bands a grid-based simulation leaves along sharp edges and
/// corners and restores the sharp edges by inserting points on them. Input vertices never move.
/// Defects (boundaries, non-manifold edges, degenerate faces) are counted in the report and
/// left unchanged; restoration goes on elsewhere. The same input and options give the same
/// output whatever the thread count.
/// \throws InvalidInput if the mesh has no triangles, an index out of range or a non-finite
///         coordinate, or an option is out of range.
RestoreResult restore(const Mesh& input, const RestoreOptions& options = {});

}  // namespace resharp
