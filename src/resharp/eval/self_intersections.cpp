#include "resharp/eval/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>

namespace resharp::eval {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

}  // namespace

std::vector<std::pair<Index, Index>> self_intersecting_pairs(const Mesh& mesh) {
    SurfaceMesh surface;
    for (const Vec3& p : mesh.positions) surface.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
    // Surface_mesh refuses faces that would make it non-manifold; remember which input face
    // each accepted face is, so that the answer speaks of input face numbers.
    std::vector<Index> input_face;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        const Triangle& t = mesh.triangles[f];
        const auto face =
            surface.add_face(SurfaceMesh::Vertex_index(t[0]), SurfaceMesh::Vertex_index(t[1]),
                             SurfaceMesh::Vertex_index(t[2]));
        if (face != SurfaceMesh::null_face()) input_face.push_back(static_cast<Index>(f));
    }
    std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
    CGAL::Polygon_mesh_processing::self_intersections(surface, std::back_inserter(pairs));
    std::vector<std::pair<Index, Index>> result;
    result.reserve(pairs.size());
    for (const auto& [a, b] : pairs) {
        const Index fa = input_face[static_cast<std::size_t>(a)];
        const Index fb = input_face[static_cast<std::size_t>(b)];
        result.emplace_back(std::min(fa, fb), std::max(fa, fb));
    }
    std::sort(result.begin(), result.end());
    return result;
}

}  // namespace resharp::eval
