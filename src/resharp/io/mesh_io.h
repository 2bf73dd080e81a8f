#pragma once
/// Reading and writing mesh files by path, the format chosen by the file extension. Include
/// this header for everything else in resharp::io.

#include <filesystem>

#include "resharp/io/atomic_file.h"
#include "resharp/io/attributes.h"
#include "resharp/io/format.h"
#include "resharp/mesh/mesh.h"

namespace resharp::io {

/// How write_mesh encodes a file.
struct WriteOptions {
    Encoding encoding = Encoding::Binary;  ///< STL and PLY; OBJ and OFF are always text
};

/// Reads the mesh file at `path` (STL, OBJ, PLY or OFF by extension, any letter case) as a
/// triangle soup; weld() makes it a Mesh.
/// \throws ReadError naming the path if the extension is unknown or the file is missing or
/// unreadable; ParseError naming the path and the line or byte if it is malformed (see
/// read_stl, read_obj, read_ply, read_off).
TriangleSoup read_mesh(const std::filesystem::path& path);

/// Writes `mesh` to `path` in the format its extension names, through an AtomicFile: on any
/// failure no file is created and an existing file is left unchanged. `attributes` (normals,
/// surface ids, colours) are written by PLY only. Byte-deterministic.
/// \throws WriteError naming the path if the extension is unknown, attributes are given for a
/// format other than PLY, the mesh or attributes cannot be written (see write_stl, write_obj,
/// write_ply, write_off), or the file cannot be created, written or moved into place.
void write_mesh(const std::filesystem::path& path, const Mesh& mesh,
                const WriteOptions& options = {}, const MeshAttributes& attributes = {});

/// As above, into an open AtomicFile (format from its target's extension) without committing
/// it, so that a command writing several files can commit them together once all are written.
/// \throws WriteError as above.
void write_mesh(AtomicFile& file, const Mesh& mesh, const WriteOptions& options = {},
                const MeshAttributes& attributes = {});

}  // namespace resharp::io
