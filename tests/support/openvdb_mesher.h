#pragma once
/// OpenVDB as a mesher the project did not write: a closed mesh voxelised into a level set
/// (openvdb::tools::meshToLevelSet) and meshed by openvdb::tools::volumeToMesh at adaptivity 0
/// (dual: one vertex per voxel at the mean of its edge crossings, near the surface but not on
/// it). Built only where OpenVDB is found (tests/CMakeLists.txt); OpenVDB's headers stay in the
/// .cpp, they are heavy to compile.

#include "resharp/mesh/mesh.h"

namespace resharp::test {

/// Takes a closed, outward mesh (#V, #F) and gives volumeToMesh's surface of its narrow-band
/// level set (3 voxels each side) on voxels of size `pitch` whose centres, the nodes of the
/// grid the dual mesh is built on, lie at integer multiples of it: each quad split along its
/// shorter diagonal, turned so that normals point out of the solid (OpenVDB winds its quads the
/// other way). Initialises OpenVDB if needed.
Mesh openvdb_dual_mesh(const Mesh& mesh, double pitch);

}  // namespace resharp::test
