#pragma once
/// OpenVDB as a mesher the project did not write: a closed mesh voxelised into a level set
/// (openvdb::tools::meshToLevelSet) and meshed by openvdb::tools::volumeToMesh at adaptivity 0
/// (dual: one vertex per voxel at the mean of its edge crossings, near the surface but not on
/// it). For the tests and the benchmarks only (extras/CMakeLists.txt builds it where OpenVDB is
/// found): the library and the `resharp` command never link OpenVDB. OpenVDB's headers stay in
/// the .cpp, they are heavy to compile.

#include "resharp/core/types.h"
#include "resharp/mesh/mesh.h"

namespace resharp::extras {

/// Takes a closed, outward mesh (#V, #F) and gives volumeToMesh's surface of its narrow-band
/// level set (3 voxels each side) on voxels of size `pitch` whose centres, the nodes of the
/// grid the dual mesh is built on, lie at origin + k * pitch (k integer per axis): each quad
/// split along its shorter diagonal, turned so that normals point out of the solid (OpenVDB
/// winds its quads the other way). Initialises OpenVDB if needed.
Mesh openvdb_dual_mesh(const Mesh& mesh, double pitch, const Vec3& origin = Vec3::Zero());

}  // namespace resharp::extras
