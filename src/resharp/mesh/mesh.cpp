#include "resharp/mesh/mesh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

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

PositionKey key_of(const Vec3& x) { return {key_bits(x.x()), key_bits(x.y()), key_bits(x.z())}; }

/// The distinct positions met so far, found by their exact bits: open addressing with linear
/// probing over indices into the welded positions, at most half full (it doubles). Written here
/// because std::unordered_map allocates a node per entry, which made welding slower than the
/// whole restoration (57 ms for mech's 172k vertices).
class PositionTable {
public:
    explicit PositionTable(std::size_t expected) { rebuild(std::bit_ceil(2 * expected + 2), {}); }

    /// The index of x in `positions`, appending it if it is new.
    Index find_or_add(const Vec3& x, std::vector<Vec3>& positions) {
        const PositionKey key = key_of(x);
        for (std::size_t slot = first_slot(key);; slot = (slot + 1) & mask_) {
            if (slots_[slot] == kNoIndex) {
                slots_[slot] = static_cast<Index>(positions.size());
                positions.push_back(x);
                if (2 * positions.size() > slots_.size()) rebuild(2 * slots_.size(), positions);
                return static_cast<Index>(positions.size() - 1);
            }
            if (key_of(positions[slots_[slot]]) == key) return slots_[slot];
        }
    }

private:
    /// The top bits of the hash: a multiplicative hash mixes best there.
    std::size_t first_slot(const PositionKey& key) const {
        return PositionKeyHash{}(key) >> shift_;
    }

    void rebuild(std::size_t size, const std::vector<Vec3>& positions) {
        slots_.assign(size, kNoIndex);
        mask_ = size - 1;
        shift_ = 64 - std::countr_zero(size);
        for (std::size_t i = 0; i < positions.size(); ++i) {
            std::size_t slot = first_slot(key_of(positions[i]));
            while (slots_[slot] != kNoIndex) slot = (slot + 1) & mask_;  // at most half full
            slots_[slot] = static_cast<Index>(i);
        }
    }

    std::vector<Index> slots_;
    std::size_t mask_ = 0;
    int shift_ = 64;
};

}  // namespace

WeldedMesh weld_mapped(const TriangleSoup& soup) {
    Mesh mesh;
    mesh.triangles.reserve(soup.triangles.size());
    // A closed genus-0 mesh has F / 2 + 2 vertices; an indexed soup lists each about once.
    // Reserved, not grown by doubling: the spare capacity would stay through the restoration
    // (up to half the positions, on the peak-memory budget); shrunk at the end if overrun.
    mesh.positions.reserve(std::min(soup.points.size(), soup.triangles.size() / 2 + 2));
    std::vector<Index> new_index(soup.points.size(), kNoIndex);
    // A closed triangle mesh has about half as many vertices as faces.
    PositionTable table(std::min(soup.points.size(), soup.triangles.size() / 2 + 1));

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
                new_index[p] = table.find_or_add(x, mesh.positions);
            }
            welded[k] = new_index[p];
        }
        mesh.triangles.push_back(welded);
    }
    mesh.positions.shrink_to_fit();
    return {std::move(mesh), std::move(new_index)};
}

Mesh weld(const TriangleSoup& soup) { return weld_mapped(soup).mesh; }

TriangleSoup to_soup(const Mesh& mesh) { return {mesh.positions, mesh.triangles}; }

}  // namespace resharp
