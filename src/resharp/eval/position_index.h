#pragma once
/// Matching vertices of two files of one simulation by position. Binary STL holds floats, the
/// oracle PLY doubles: a point is found by its exact coordinates when the other side has them
/// (PLY and OBJ written by resharp keep doubles), else by its float rounding. Two vertices of a
/// fine grid mesh can round to one float (a surface passing within a few micrometres of a grid
/// node): the exact match keeps them apart.

#include <array>
#include <optional>
#include <span>
#include <unordered_map>

#include "resharp/core/types.h"

namespace resharp::eval {

class PositionIndex {
public:
    /// Indexes `points` (#P) by their coordinates and by their float rounding; of points that
    /// round alike, the first is kept for the rounding.
    explicit PositionIndex(std::span<const Vec3> points);

    /// The index into the constructor's points of the one equal to `p`, else, if `p` is a float
    /// (read from a file that keeps floats), of the one that rounds to it, if any.
    std::optional<Index> find(const Vec3& p) const;

private:
    template <class T>
    struct Key {
        std::array<T, 3> c;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        template <class T>
        std::size_t operator()(const Key<T>& k) const;
    };
    template <class T>
    static Key<T> key_of(const Vec3& p) {
        return {{static_cast<T>(p.x()), static_cast<T>(p.y()), static_cast<T>(p.z())}};
    }

    std::unordered_map<Key<double>, Index, KeyHash> exact_;
    std::unordered_map<Key<float>, Index, KeyHash> rounded_;
};

}  // namespace resharp::eval
