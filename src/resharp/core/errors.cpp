#include "resharp/core/errors.h"

namespace resharp {
namespace {

std::string describe(const FileLocation& location) {
    const char* unit = location.kind == FileLocation::Kind::Line ? "line " : "byte ";
    return unit + std::to_string(location.value);
}

}  // namespace

IoError::IoError(std::string path, const std::string& reason)
    : Error(path + ": " + reason), path_(std::move(path)) {}

ParseError::ParseError(std::string path, FileLocation location, const std::string& reason)
    : ReadError(std::move(path), describe(location) + ": " + reason), location_(location) {}

}  // namespace resharp
