#pragma once
/// Internal-invariant checks. Never used to validate input: input errors throw (core/errors.h).
/// RESHARP_ASSERT is on in debug builds; RESHARP_EXPENSIVE_ASSERT only with
/// RESHARP_ENABLE_EXPENSIVE_ASSERTS, for checks that cost as much as the stage itself.

#include <cstdio>
#include <cstdlib>

namespace resharp::detail {
[[noreturn]] inline void assertion_failed(const char* expr, const char* file, int line) {
    std::fprintf(stderr, "resharp internal error: %s at %s:%d\n", expr, file, line);
    std::abort();
}
}  // namespace resharp::detail

#ifdef NDEBUG
#define RESHARP_ASSERT(expr) ((void)0)
#else
#define RESHARP_ASSERT(expr) \
    ((expr) ? (void)0 : ::resharp::detail::assertion_failed(#expr, __FILE__, __LINE__))
#endif

#ifdef RESHARP_ENABLE_EXPENSIVE_ASSERTS
#define RESHARP_EXPENSIVE_ASSERT(expr) \
    ((expr) ? (void)0 : ::resharp::detail::assertion_failed(#expr, __FILE__, __LINE__))
#else
#define RESHARP_EXPENSIVE_ASSERT(expr) ((void)0)
#endif
