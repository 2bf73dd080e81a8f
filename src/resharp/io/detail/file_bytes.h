#pragma once
/// Internal to resharp::io: whole files and streams into memory, so every parser works on one
/// contiguous buffer whose size is known before any count in it is trusted.

#include <filesystem>
#include <istream>
#include <string>

namespace resharp::io::detail {

/// Every byte of the file. \throws ReadError if it is missing, a directory or unreadable.
std::string read_file_bytes(const std::filesystem::path& path);

/// Every byte left in `in`. \throws ReadError naming `name` if the stream fails.
std::string read_stream_bytes(std::istream& in, const std::string& name);

}  // namespace resharp::io::detail
