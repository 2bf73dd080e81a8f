#pragma once
/// Internal to resharp::io: what writers check before writing, so no writer produces a file its
/// own reader would refuse.

#include <string>

#include "resharp/io/attributes.h"
#include "resharp/mesh/mesh.h"

namespace resharp::io::detail {

/// Why `mesh` cannot be written with `attributes` (an index out of range, a NaN or infinite
/// coordinate or normal, no triangles, an attribute neither empty nor one per element), or ""
/// if it can.
std::string find_unwritable(const Mesh& mesh, const MeshAttributes& attributes = {});

/// \throws InvalidInput with find_unwritable's reason if there is one.
void require_writable(const Mesh& mesh, const MeshAttributes& attributes = {});

}  // namespace resharp::io::detail
