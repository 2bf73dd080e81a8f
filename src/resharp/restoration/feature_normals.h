#pragma once
/// Feature normals at the vertices of edge and corner triangles (paper §5.1, eq. 5.1).

#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/mesh.h"
#include "resharp/restoration/band_classification.h"

namespace resharp {

/// Per vertex (#V): at each vertex of an edge or corner triangle, N = sum(theta_i N_i) / sum(theta_i) over
/// the incident faces of the vertex's own feature patch (eq. 5.1), normalised; theta_i is the
/// face's angle at the vertex. Faces whose three vertices all lie on that patch are preferred:
/// a face that only leans into the patch from a band would tilt N towards the neighbouring
/// feature. A vertex all of whose faces lie in bands takes the mean of its same-patch neighbours'
/// normals. Zero at vertices off the bands, without a patch, or where nothing can tell.
std::vector<Vec3> feature_normals(const Mesh& mesh, const Connectivity& connectivity,
                                  const std::vector<Vec3>& face_normals,
                                  const std::vector<Index>& face_patch,
                                  const std::vector<Index>& vertex_patch,
                                  const BandClassification& bands);

}  // namespace resharp
