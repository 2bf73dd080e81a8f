#include "resharp/io/detail/byte_cursor.h"

#include "resharp/core/errors.h"

namespace resharp::io::detail {

void ByteCursor::require(std::size_t count, std::string_view what) const {
    if (count <= remaining()) return;
    fail("file truncated: " + std::string(what) + " needs " + std::to_string(count) +
         " bytes, only " + std::to_string(remaining()) + " left");
}

void ByteCursor::fail_at(std::size_t offset, const std::string& reason) const {
    throw ParseError(name_, FileLocation::byte(offset), reason);
}

}  // namespace resharp::io::detail
