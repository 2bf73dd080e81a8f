#include "resharp/mesh/mesh.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>

#include "resharp/core/errors.h"

namespace resharp {
namespace {

struct PositionKey {
    std::uint64_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
    std::size_t operator()(const PositionKey& k) const {
        // splitmix-style mixing: the raw bit patterns of nearby doubles differ only in low bits.
        std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
        h ^= (k.y + 0xBF58476D1CE4E5B9ull + (h << 6) + (h >> 2));
        h ^= (k.z + 0x94D049BB133111EBull + (h << 6) + (h >> 2));
        h ^= h >> 31;
        return static_cast<std::size_t>(h * 0xD6E8FEB86659FD93ull);
    }
};

std::uint64_t key_bits(double value) {
    return std::bit_cast<std::uint64_t>(value == 0.0 ? 0.0 : value);  // -0 welds with +0
}

}  // namespace

Mesh weld(const TriangleSoup& soup) {
    Mesh mesh;
    mesh.triangles.reserve(soup.triangles.size());
    std::vector<Index> new_index(soup.points.size(), kNoIndex);
    std::unordered_map<PositionKey, Index, PositionKeyHash> index_of;
    index_of.reserve(soup.points.size() / 2 + 1);

    for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
        Triangle welded{};
        for (int k = 0; k < 3; ++k) {
            const Index p = soup.triangles[f][k];
            if (p >= soup.points.size()) {
                throw InvalidInput("triangle " + std::to_string(f) + " uses point " +
                                   std::to_string(p) + " but there are only " +
                                   std::to_string(soup.points.size()) + " points");
            }
            if (new_index[p] == kNoIndex) {
                const Vec3& x = soup.points[p];
                if (!x.allFinite()) {
                    throw InvalidInput("point " + std::to_string(p) +
                                       " has a NaN or infinite coordinate");
                }
                const PositionKey key{key_bits(x.x()), key_bits(x.y()), key_bits(x.z())};
                const auto [it, inserted] =
                    index_of.try_emplace(key, static_cast<Index>(mesh.positions.size()));
                if (inserted) mesh.positions.push_back(x);
                new_index[p] = it->second;
            }
            welded[k] = new_index[p];
        }
        mesh.triangles.push_back(welded);
    }
    return mesh;
}

TriangleSoup to_soup(const Mesh& mesh) { return {mesh.positions, mesh.triangles}; }

}  // namespace resharp
