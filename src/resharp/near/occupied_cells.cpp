#include "resharp/near/occupied_cells.h"

#include <algorithm>
#include <cmath>

namespace resharp {

OccupiedCells::OccupiedCells(const std::vector<Vec3>& positions, const Grid& grid) : grid_(grid) {
    cells_.reserve(positions.size());
    for (const Vec3& x : positions) cells_.push_back(key_of(x));
    std::sort(cells_.begin(), cells_.end());
    cells_.erase(std::unique(cells_.begin(), cells_.end()), cells_.end());
}

bool OccupiedCells::holds_vertex(const Vec3& x) const {
    return std::binary_search(cells_.begin(), cells_.end(), key_of(x));
}

std::uint64_t OccupiedCells::key_of(const Vec3& x) const {
    // The readers refuse non-finite coordinates; a quotient past the 64-bit range (a mesh 2^62
    // pitches wide) is held to its end, where a cast would be undefined.
    constexpr double kFarthest = 4e18;
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double index = std::floor((x[axis] - grid_.origin[axis]) / grid_.pitch);
        const auto i = static_cast<std::int64_t>(std::clamp(index, -kFarthest, kFarthest));
        key = mix(key ^ static_cast<std::uint64_t>(i));
    }
    return key;
}

std::uint64_t OccupiedCells::mix(std::uint64_t z) {
    // SplitMix64's finaliser (Steele, Lea and Flood, "Fast splittable pseudorandom number
    // generators", OOPSLA 2014): every input bit reaches every output bit.
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

}  // namespace resharp
