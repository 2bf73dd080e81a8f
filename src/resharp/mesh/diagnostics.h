#pragma once
/// Counts of the defects the method cannot treat, found before any stage runs (docs/design.md §6).

#include <cstddef>
#include <vector>

#include "resharp/mesh/connectivity.h"
#include "resharp/mesh/duplicate_faces.h"
#include "resharp/mesh/mesh.h"

namespace resharp {

struct MeshDiagnostics {
    std::size_t boundary_edges = 0;        ///< edges with one face
    std::size_t nonmanifold_edges = 0;     ///< edges with three or more faces
    std::size_t inconsistent_edges = 0;    ///< edges whose two faces disagree on orientation
    std::size_t nonmanifold_vertices = 0;  ///< vertices whose faces form more than one fan
    std::size_t degenerate_faces = 0;      ///< faces with a repeated vertex or zero area
    /// later copies of exact duplicate faces plus pairs of opposite faces (duplicate_faces.h)
    std::size_t duplicate_faces = 0;
    std::size_t isolated_vertices = 0;  ///< vertices no face uses
    std::size_t components = 0;         ///< edge-connected pieces of the surface

    /// True when the mesh is a closed, oriented 2-manifold without degenerate faces.
    bool is_clean_closed_manifold() const {
        return boundary_edges == 0 && nonmanifold_edges == 0 && inconsistent_edges == 0 &&
               nonmanifold_vertices == 0 && degenerate_faces == 0 && duplicate_faces == 0;
    }
};

/// Per face (#F): true where the face has a repeated vertex or zero area.
std::vector<bool> find_degenerate_faces(const Mesh& mesh);

/// Inspects the mesh; never throws.
MeshDiagnostics diagnose(const Mesh& mesh, const Connectivity& connectivity);

/// diagnose(), given what find_duplicate_faces() found on the same mesh and connectivity.
MeshDiagnostics diagnose(const Mesh& mesh, const Connectivity& connectivity,
                         const DuplicateFaces& duplicates);

}  // namespace resharp
