#include "malloc_tuning.h"

#include <algorithm>
#include <climits>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace resharp::cli {

void tune_malloc(std::size_t files_at_once) {
#if defined(__GLIBC__)
    mallopt(M_ARENA_MAX, static_cast<int>(std::clamp<std::size_t>(files_at_once, 1, INT_MAX)));
    // Blocks below 32 MiB (the most glibc takes: 4 MiB * sizeof(long)) come from the heap, and
    // the heap is never trimmed.
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, INT_MAX);
#else
    (void)files_at_once;
#endif
}

}  // namespace resharp::cli
