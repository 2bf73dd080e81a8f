#pragma once
/// Matching vertices of two files of one simulation by position. Binary STL holds floats, the
/// oracle PLY doubles, so both sides are keyed by their float rounding (two vertices of a grid
/// mesh are never that close).

#include <array>
#include <optional>
#include <span>
#include <unordered_map>

#include "resharp/core/types.h"

namespace resharp::eval {

class PositionIndex {
public:
    /// Indexes `points` (#P) by their float rounding; of points that round alike, the first is
    /// kept.
    explicit PositionIndex(std::span<const Vec3> points);

    /// The index into the constructor's points of the one that rounds as `p` does, if any.
    std::optional<Index> find(const Vec3& p) const;

private:
    struct Key {
        std::array<float, 3> c;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const;
    };
    static Key key_of(const Vec3& p);

    std::unordered_map<Key, Index, KeyHash> index_;
};

}  // namespace resharp::eval
