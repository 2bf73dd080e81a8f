#pragma once
/// Wavefront OBJ: reader and writer for the geometry (`v` and `f` records).

#include <istream>
#include <ostream>
#include <string>
#include <string_view>

#include "resharp/mesh/mesh.h"

namespace resharp::io {

/// Reads an OBJ file held in memory. `bytes` is the whole file; `name` names it in messages.
/// Takes `v x y z` (up to four more numbers, w or a colour, are ignored) and `f` records whose
/// corners are `v`, `v/vt`, `v//vn` or `v/vt/vn`, with 1-based or negative (relative) indices;
/// polygons are fan-triangulated. Other OBJ records (vt, vn, g, o, s, usemtl, mtllib, l, p,
/// free-form geometry) and `#` comments are skipped.
/// Returns the `v` points in file order and the triangles.
/// \throws ParseError naming `name` and the line for an unknown record, a malformed, NaN or
/// infinite number, an index that is 0 or refers to no vertex defined above it, a face with
/// fewer than 3 corners, or no triangles at all.
TriangleSoup read_obj(std::string_view bytes, const std::string& name);

/// Reads an OBJ file from the rest of `in`. \throws ReadError if the stream fails, ParseError as
/// the overload above.
TriangleSoup read_obj(std::istream& in, const std::string& name);

/// Writes `mesh` as `v` and `f` records, coordinates in the shortest decimal form that reads
/// back exactly. Byte-deterministic. Check `out`'s state afterwards.
/// \throws InvalidInput if `mesh` has no triangles, an index out of range or a NaN coordinate.
void write_obj(std::ostream& out, const Mesh& mesh);

}  // namespace resharp::io
