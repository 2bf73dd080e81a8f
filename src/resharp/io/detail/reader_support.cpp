#include "resharp/io/detail/reader_support.h"

namespace resharp::io::detail {

void append_fan(std::span<const Index> polygon, std::vector<Triangle>& triangles) {
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
        triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
    }
}

bool fits(std::uint64_t count, std::uint64_t min_bytes, std::uint64_t available) {
    return min_bytes == 0 || count <= available / min_bytes;
}

}  // namespace resharp::io::detail
