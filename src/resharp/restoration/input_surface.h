#pragma once
/// The input mesh as the stages after segmentation read it: positions, adjacency and normals,
/// built once by the pipeline and never changed.

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/geometry.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

struct InputSurface {
    const Mesh& mesh;
    const Connectivity& connectivity;
    const SurfaceNormals& normals;  ///< unit face normals (#F) and vertex normals (#V)
};

}  // namespace resharp
