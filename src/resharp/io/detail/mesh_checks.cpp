#include "resharp/io/detail/mesh_checks.h"

#include <utility>

#include "resharp/core/errors.h"

namespace resharp::io::detail {
namespace {

std::string find_bad_geometry(const Mesh& mesh) {
    if (mesh.triangles.empty()) return "the mesh has no triangles";
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!mesh.positions[v].allFinite()) {
            return "vertex " + std::to_string(v) + " has a NaN or infinite coordinate";
        }
    }
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        for (const Index v : mesh.triangles[f]) {
            if (v >= mesh.positions.size()) {
                return "triangle " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                       " of " + std::to_string(mesh.positions.size());
            }
        }
    }
    return {};
}

// "" if `size` is 0 or `expected`.
std::string count_mismatch(const char* what, std::size_t size, std::size_t expected,
                           const char* per) {
    if (size == 0 || size == expected) return {};
    return std::string(what) + " has " + std::to_string(size) + " values for " +
           std::to_string(expected) + " " + per;
}

std::string find_bad_attributes(const Mesh& mesh, const MeshAttributes& attributes) {
    const std::size_t v = mesh.vertex_count();
    for (std::string problem :
         {count_mismatch("vertex_normals", attributes.vertex_normals.size(), v, "vertices"),
          count_mismatch("vertex_surfaces", attributes.vertex_surfaces.size(), v, "vertices"),
          count_mismatch("vertex_surface_points", attributes.vertex_surface_points.size(), v,
                         "vertices"),
          count_mismatch("vertex_colors", attributes.vertex_colors.size(), v, "vertices"),
          count_mismatch("face_colors", attributes.face_colors.size(), mesh.face_count(),
                         "faces")}) {
        if (!problem.empty()) return problem;
    }
    for (const auto& [values, what] :
         {std::pair{attributes.vertex_normals, "normal"},
          std::pair{attributes.vertex_surface_points, "surface point"}}) {
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (!values[i].allFinite()) {
                return std::string(what) + " of vertex " + std::to_string(i) +
                       " is NaN or infinite";
            }
        }
    }
    return {};
}

}  // namespace

std::string find_unwritable(const Mesh& mesh, const MeshAttributes& attributes) {
    std::string problem = find_bad_geometry(mesh);
    return problem.empty() ? find_bad_attributes(mesh, attributes) : problem;
}

void require_writable(const Mesh& mesh, const MeshAttributes& attributes) {
    if (std::string problem = find_unwritable(mesh, attributes); !problem.empty()) {
        throw InvalidInput(problem);
    }
}

}  // namespace resharp::io::detail
