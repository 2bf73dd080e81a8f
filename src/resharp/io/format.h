#pragma once
/// Mesh file formats and how a path names one.

#include <filesystem>
#include <optional>

namespace resharp::io {

/// The mesh file formats resharp reads and writes.
enum class MeshFormat { Stl, Obj, Ply, Off };

/// How STL and PLY files store numbers. OBJ and OFF are always text.
enum class Encoding { Binary, Ascii };

/// The format named by the extension of `path` (.stl .obj .ply .off, any letter case), or
/// nullopt for any other extension or none.
std::optional<MeshFormat> format_from_path(const std::filesystem::path& path);

/// As format_from_path, for a file about to be read.
/// \throws ReadError naming the path if the extension names no supported format.
MeshFormat format_for_reading(const std::filesystem::path& path);

/// As format_from_path, for a file about to be written.
/// \throws WriteError naming the path if the extension names no supported format.
MeshFormat format_for_writing(const std::filesystem::path& path);

/// The usual name of the format: "STL", "OBJ", "PLY" or "OFF".
const char* format_name(MeshFormat format);

}  // namespace resharp::io
