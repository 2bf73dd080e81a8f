#pragma once
/// Geomview OFF: reader and writer.

#include <istream>
#include <ostream>
#include <string>
#include <string_view>

#include "resharp/mesh/mesh.h"

namespace resharp::io {

/// Reads an OFF file held in memory. `bytes` is the whole file; `name` names it in messages.
/// Takes the `OFF` header (also `COFF`, `NOFF`, `CNOFF`, whose extra per-vertex values are
/// skipped), the vertex, face and edge counts, one vertex per line and one face per line
/// (`n i1 ... in`, n >= 3, fan-triangulated, optional colour values after the indices skipped).
/// `#` starts a comment. Returns the vertices and the triangles.
/// \throws ParseError naming `name` and the line for a missing or unsupported header, negative
/// counts or counts the file is too small to hold, a line with too few or too many numbers, a
/// malformed, NaN or infinite number, an index out of range, a face with fewer than 3 corners,
/// data after the last face, or no triangles at all.
TriangleSoup read_off(std::string_view bytes, const std::string& name);

/// Reads an OFF file from the rest of `in`. \throws ReadError if the stream fails, ParseError as
/// the overload above.
TriangleSoup read_off(std::istream& in, const std::string& name);

/// Writes `mesh` as OFF, coordinates in the shortest decimal form that reads back exactly.
/// Byte-deterministic. Check `out`'s state afterwards.
/// \throws InvalidInput if `mesh` has no triangles, an index out of range or a NaN coordinate.
void write_off(std::ostream& out, const Mesh& mesh);

}  // namespace resharp::io
