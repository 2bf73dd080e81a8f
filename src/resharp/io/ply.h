#pragma once
/// PLY (ascii, binary_little_endian, binary_big_endian): reader, reader with extra properties,
/// and writer with attributes.

#include <filesystem>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "resharp/io/attributes.h"
#include "resharp/io/format.h"
#include "resharp/mesh/mesh.h"

namespace resharp::io {

/// The values of one scalar PLY property, converted to double (exact for every PLY type).
struct PlyProperty {
    std::string name;
    std::vector<double> values;
};

/// A PLY mesh with the scalar properties its vertex and face elements carry besides positions
/// and vertex indices (normals, surface ids, colours, ...).
struct PlyMesh {
    TriangleSoup soup;
    /// Every scalar vertex property but x, y, z, in file order; #P values each.
    std::vector<PlyProperty> vertex_properties;
    /// Every scalar face property, in file order; #T values each: a polygon's value is repeated
    /// for each triangle of its fan.
    std::vector<PlyProperty> face_properties;

    /// The values of the vertex property called `name`, or nullptr if there is none.
    const std::vector<double>* vertex_property(std::string_view name) const;
    /// The values of the face property called `name`, or nullptr if there is none.
    const std::vector<double>* face_property(std::string_view name) const;
};

/// Reads a PLY file held in memory. `bytes` is the whole file; `name` names it in messages.
/// Needs a `vertex` element with scalar x, y, z (any numeric type, any order) and a `face`
/// element with a `vertex_indices` or `vertex_index` list of integers (count and index of any
/// integer type); polygons are fan-triangulated. Other properties and elements are skipped.
/// Returns the vertices and the triangles.
/// \throws ParseError naming `name` and the line (header, ASCII body) or byte offset (binary
/// body) for a malformed header, counts or list lengths the file is too small to hold, a
/// truncated body or bytes after it, a malformed number or one out of its type's range, a NaN or
/// infinite floating-point value, an index out of range, a face with fewer than 3 corners, or no
/// triangles at all.
TriangleSoup read_ply(std::string_view bytes, const std::string& name);

/// Reads a PLY file from the rest of `in`. \throws ReadError if the stream fails, ParseError as
/// the overload above.
TriangleSoup read_ply(std::istream& in, const std::string& name);

/// As read_ply, also keeping the extra scalar properties (for oracle files: nx, ny, nz, surface).
/// \throws ParseError as read_ply.
PlyMesh read_ply_with_properties(std::string_view bytes, const std::string& name);

/// As above, for the file at `path`. \throws ReadError if it cannot be read, ParseError as
/// read_ply.
PlyMesh read_ply_with_properties(const std::filesystem::path& path);

/// Writes `mesh` as PLY in `encoding` with the non-empty `attributes`: `double x, y, z`, then
/// `double nx, ny, nz`, `int surface`, `double sx, sy, sz`, `uchar red, green, blue` per vertex; a
/// `list uchar int vertex_indices` and `uchar red, green, blue` per face. Doubles keep every
/// bit (ASCII uses the shortest decimal form that reads back exactly). Byte-deterministic.
/// Check `out`'s state afterwards.
/// \throws InvalidInput if `mesh` has no triangles, an index out of range or a NaN coordinate,
/// or an attribute is neither empty nor one per element, or a normal or surface point is NaN or
/// infinite.
void write_ply(std::ostream& out, const Mesh& mesh, Encoding encoding,
               const MeshAttributes& attributes = {});

}  // namespace resharp::io
