#pragma once
/// How many heaps the C library's allocator keeps for the command's threads.

#include <cstddef>

namespace resharp::cli {

/// Takes how many files the command restores at once and caps glibc's malloc arenas at that
/// many (elsewhere: does nothing). glibc gives each thread that allocates an arena of its own,
/// and memory freed in one arena serves only later requests in that one: on two threads,
/// whose second thread builds part of the detection, restore's peak resident set was 4 to 5
/// MiB above one thread's on mech, frogface and cavity (6 to 7 %), and 1.5 MiB on
/// relief_hang.stl, which put it over docs/design.md's budget of 300 bytes per input triangle.
/// The stages allocate a few large arrays each, not many small ones, so sharing one arena
/// costs no time that shows (docs/benchmarks.md). Call before starting the threads.
void limit_malloc_arenas(std::size_t files_at_once);

}  // namespace resharp::cli
