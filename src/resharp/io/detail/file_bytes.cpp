#include "resharp/io/detail/file_bytes.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "resharp/core/errors.h"

namespace resharp::io::detail {

std::string read_file_bytes(const std::filesystem::path& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) {
        throw ReadError(path.string(), "no such file");
    }
    if (status.type() == std::filesystem::file_type::directory) {
        throw ReadError(path.string(), "is a directory, not a mesh file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ReadError(path.string(), std::string("cannot open: ") + std::strerror(errno));
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return read_stream_bytes(in, path.string());  // not a regular file: read to the end
    std::string bytes(size, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) {
        throw ReadError(path.string(), "read failed after " + std::to_string(in.gcount()) + " of " +
                                           std::to_string(size) + " bytes");
    }
    return bytes;
}

std::string read_stream_bytes(std::istream& in, const std::string& name) {
    std::string bytes;
    char block[1 << 16];
    while (in.read(block, sizeof block) || in.gcount() > 0) {
        bytes.append(block, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad())
        throw ReadError(name, "read failed after " + std::to_string(bytes.size()) + " bytes");
    return bytes;
}

}  // namespace resharp::io::detail
