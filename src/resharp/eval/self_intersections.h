#pragma once
/// Exact self-intersection test of a triangle mesh (CGAL, exact predicates).

#include <cstddef>
#include <utility>
#include <vector>

#include "resharp/mesh/mesh.h"

namespace resharp::eval {

/// Pairs of faces that intersect other than along a shared edge or at a shared vertex, as
/// CGAL::Polygon_mesh_processing::self_intersections finds them with exact predicates. Each
/// pair (f, g) has f < g and the list is sorted.
std::vector<std::pair<Index, Index>> self_intersecting_pairs(const Mesh& mesh);

}  // namespace resharp::eval
