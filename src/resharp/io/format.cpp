#include "resharp/io/format.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "resharp/core/errors.h"

namespace resharp::io {
namespace {

constexpr const char* kSupported = "expected extension .stl, .obj, .ply or .off";

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string unknown_format_reason(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    const std::string what = ext.empty() ? "no file extension" : "unknown extension '" + ext + "'";
    return what + " (" + kSupported + ")";
}

}  // namespace

std::optional<MeshFormat> format_from_path(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".stl") return MeshFormat::Stl;
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".off") return MeshFormat::Off;
    return std::nullopt;
}

MeshFormat format_for_reading(const std::filesystem::path& path) {
    if (const auto format = format_from_path(path)) return *format;
    throw ReadError(path.string(), unknown_format_reason(path));
}

MeshFormat format_for_writing(const std::filesystem::path& path) {
    if (const auto format = format_from_path(path)) return *format;
    throw WriteError(path.string(), unknown_format_reason(path));
}

const char* format_name(MeshFormat format) {
    switch (format) {
        case MeshFormat::Stl:
            return "STL";
        case MeshFormat::Obj:
            return "OBJ";
        case MeshFormat::Ply:
            return "PLY";
        case MeshFormat::Off:
            return "OFF";
    }
    return "?";
}

}  // namespace resharp::io
