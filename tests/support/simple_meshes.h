#pragma once
/// Small meshes written out by hand, for tests of mesh building and diagnostics.

#include "resharp/mesh/mesh.h"

namespace resharp::test {

/// The axis-aligned box [0,sx]x[0,sy]x[0,sz] as 8 vertices and 12 outward triangles.
Mesh box_mesh(double sx = 1.0, double sy = 1.0, double sz = 1.0);

/// The same box as an STL-like soup: three points per triangle.
TriangleSoup box_soup(double sx = 1.0, double sy = 1.0, double sz = 1.0);

}  // namespace resharp::test
