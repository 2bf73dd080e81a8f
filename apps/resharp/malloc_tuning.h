#pragma once
/// How the C library's allocator serves the command's stages (glibc only; elsewhere nothing).

#include <cstddef>

namespace resharp::cli {

/// Takes how many files the command restores at once and sets glibc's malloc for the
/// restoration's few large arrays per stage (docs/benchmarks.md, "Peak memory" and "The
/// allocator"). Call before starting any thread.
/// - One arena per file restored at once. glibc gives each thread that allocates an arena of
///   its own, and memory freed in one serves only later requests in that one: on two threads,
///   whose second thread builds part of the detection, the peak resident set was 4 to 5 MiB
///   above one thread's on mech, frogface and cavity, and 1.5 MiB on relief_hang.stl, which put
///   it over docs/design.md's budget of 300 bytes per input triangle.
/// - Freed memory kept for reuse. By default glibc maps blocks from 128 KiB up (the bound
///   rising with the blocks freed) and returns them when freed, and gives back the top of its
///   heap, so each stage's arrays were faulted in again page by page (impeller: 32,000 page
///   faults a run); kept, restore() took 4 to 11 % less time on the four benchmark parts on two
///   threads (medians of three comparisons), for up to 6.4 % more peak memory.
void tune_malloc(std::size_t files_at_once);

}  // namespace resharp::cli
