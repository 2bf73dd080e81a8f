#pragma once
/// STL, binary and ASCII: reader and writer.

#include <istream>
#include <ostream>
#include <string>
#include <string_view>

#include "resharp/io/format.h"
#include "resharp/mesh/mesh.h"

namespace resharp::io {

/// Reads an STL file held in memory. Binary and ASCII are told apart by content: a file is
/// binary unless it starts with "solid", or if it does, when its size is 84 + 50 n for the n in
/// its header or it holds a NUL byte (as many binary files whose header starts with "solid" do).
/// `bytes` is the whole file; `name` names it in messages.
/// Returns three points per triangle, in file order (weld() merges them); facet normals and
/// attribute bytes are ignored.
/// \throws ParseError naming `name` and the byte offset (binary) or line (ASCII) for a
/// truncated file, a triangle count the file size contradicts, trailing bytes, a NaN or infinite
/// coordinate, a malformed or missing keyword or number, a facet without exactly 3 vertices, or
/// no triangles at all.
TriangleSoup read_stl(std::string_view bytes, const std::string& name);

/// Reads an STL file from the rest of `in`. \throws ReadError if the stream fails, ParseError as
/// the overload above.
TriangleSoup read_stl(std::istream& in, const std::string& name);

/// Writes `mesh` as STL in `encoding`: one facet per triangle with its unit normal (zero for a
/// degenerate triangle). Binary rounds coordinates to float as the format requires; ASCII writes
/// the shortest decimal form of each double, which reads back exactly. Byte-deterministic; the
/// binary header does not start with "solid". Check `out`'s state afterwards.
/// \throws InvalidInput if `mesh` has no triangles, an index out of range, or a coordinate that
/// is NaN, infinite or beyond float range.
void write_stl(std::ostream& out, const Mesh& mesh, Encoding encoding);

}  // namespace resharp::io
