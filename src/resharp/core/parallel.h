#pragma once
/// Parallel loops over indices, for the stages whose elements are independent: each index is
/// visited once, so a body that writes only its own element gives the same result whatever the
/// number of threads.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace resharp {

/// Calls body(i) for every i below count, in parallel blocks of at least `grain`.
template <class Body>
void for_each_index(std::size_t count, std::size_t grain, Body&& body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
    });
}

/// for_each_index() with a scratch object per block, body(i, scratch): for loops that reuse a
/// buffer from one index to the next instead of allocating one per index.
template <class Scratch, class Body>
void for_each_index_with(std::size_t count, std::size_t grain, Body&& body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain), [&](const auto& range) {
        Scratch scratch;
        for (std::size_t i = range.begin(); i != range.end(); ++i) body(i, scratch);
    });
}

}  // namespace resharp
