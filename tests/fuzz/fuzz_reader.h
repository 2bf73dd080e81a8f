#pragma once
/// What every reader fuzzer checks. A reader may refuse an input only with ParseError; any other
/// exception escapes and libFuzzer reports it as a crash. An accepted soup must be usable: at
/// least one triangle, indices in range, finite points, weld() accepting it, and a PLY round
/// trip giving the same mesh back.

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>

#include "resharp/core/errors.h"
#include "resharp/io/ply.h"
#include "resharp/mesh/mesh.h"

namespace resharp::fuzz {

inline void require(bool condition) {
    if (!condition) std::abort();
}

inline void check_soup(const TriangleSoup& soup) {
    require(!soup.triangles.empty());
    for (const Vec3& p : soup.points) require(p.allFinite());
    for (const Triangle& t : soup.triangles) {
        for (const Index v : t) require(v < soup.points.size());
    }
    const Mesh mesh = weld(soup);
    std::ostringstream out;
    io::write_ply(out, mesh, io::Encoding::Binary);
    const TriangleSoup again = io::read_ply(out.str(), "round-trip.ply");
    require(again.points == mesh.positions && again.triangles == mesh.triangles);
}

/// Runs `read(bytes, name)` on the fuzzer's input and checks what it returns.
template <class Read>
int run(const std::uint8_t* data, std::size_t size, Read read) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        check_soup(read(bytes));
    } catch (const ParseError&) {
        // The expected way to refuse hostile input.
    }
    return 0;
}

}  // namespace resharp::fuzz
