#include "resharp/io/mesh_io.h"

#include "resharp/core/errors.h"
#include "resharp/io/atomic_file.h"
#include "resharp/io/detail/file_bytes.h"
#include "resharp/io/obj.h"
#include "resharp/io/off.h"
#include "resharp/io/ply.h"
#include "resharp/io/stl.h"

namespace resharp::io {
namespace {

void write_format(std::ostream& out, MeshFormat format, const Mesh& mesh,
                  const WriteOptions& options, const MeshAttributes& attributes) {
    switch (format) {
        case MeshFormat::Stl:
            return write_stl(out, mesh, options.encoding);
        case MeshFormat::Obj:
            return write_obj(out, mesh);
        case MeshFormat::Ply:
            return write_ply(out, mesh, options.encoding, attributes);
        case MeshFormat::Off:
            return write_off(out, mesh);
    }
}

}  // namespace

TriangleSoup read_mesh(const std::filesystem::path& path) {
    const MeshFormat format = format_for_reading(path);
    const std::string bytes = detail::read_file_bytes(path);
    const std::string name = path.string();
    switch (format) {
        case MeshFormat::Stl:
            return read_stl(bytes, name);
        case MeshFormat::Obj:
            return read_obj(bytes, name);
        case MeshFormat::Ply:
            return read_ply(bytes, name);
        case MeshFormat::Off:
            return read_off(bytes, name);
    }
    throw ReadError(name, "unknown format");
}

void write_mesh(AtomicFile& file, const Mesh& mesh, const WriteOptions& options,
                const MeshAttributes& attributes) {
    const std::filesystem::path& path = file.target();
    const MeshFormat format = format_for_writing(path);
    if (!attributes.empty() && format != MeshFormat::Ply) {
        throw WriteError(path.string(), std::string("only PLY stores normals, surface ids and "
                                                    "colours; cannot write them as ") +
                                            format_name(format));
    }
    try {
        write_format(file.stream(), format, mesh, options, attributes);
    } catch (const InvalidInput& e) {
        throw WriteError(path.string(), e.what());
    }
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options,
                const MeshAttributes& attributes) {
    format_for_writing(path);  // an unknown extension fails before any file is created
    AtomicFile file(path);
    write_mesh(file, mesh, options, attributes);
    file.commit();
}

}  // namespace resharp::io
