#pragma once
/// Union-find over 0..n-1 with path halving. The smaller index always becomes the root, so the
/// representatives do not depend on the order of unions: results stay deterministic.

#include <algorithm>
#include <numeric>
#include <vector>

#include "resharp/core/types.h"

namespace resharp {

class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), Index{0});
    }
    Index find(Index x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    /// Joins the sets of a and b; returns false if they were already one set.
    bool unite(Index a, Index b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        parent_[std::max(a, b)] = std::min(a, b);
        return true;
    }

private:
    std::vector<Index> parent_;
};

}  // namespace resharp
