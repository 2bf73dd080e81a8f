#include "malloc_arenas.h"

#include <algorithm>
#include <climits>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace resharp::cli {

void limit_malloc_arenas(std::size_t files_at_once) {
#if defined(__GLIBC__)
    // A refused value (none is: any positive count is taken) only leaves glibc's default.
    mallopt(M_ARENA_MAX, static_cast<int>(std::clamp<std::size_t>(files_at_once, 1, INT_MAX)));
#else
    (void)files_at_once;
#endif
}

}  // namespace resharp::cli
