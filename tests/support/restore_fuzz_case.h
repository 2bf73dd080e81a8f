#pragma once
/// One case of the restore() fuzzer (tests/fuzz/restore_fuzzer.cpp), apart from libFuzzer so that
/// the test suite replays the committed cases (tests/fuzz/corpus/restore) with any compiler.
///
/// The bytes pick one of six small parts the simulator makes (tests/support/small_parts.h, 2.6k to
/// 6k triangles, by four meshers) and damage it the ways other meshers and exports damage meshes:
/// jitter, runs of faces dropped, faces duplicated (as they are or turned over) or turned over in
/// place, vertices merged; they may also set a stop callback that fires at a given question or a
/// deadline, and the harm rounds allowed. restore() then runs on one thread.

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "resharp/mesh/mesh.h"
#include "resharp/pipeline/options.h"

namespace resharp::test {

/// What a case restores, and how.
struct RestoreFuzzInput {
    Mesh mesh;                ///< the damaged part
    RestoreOptions options;   ///< one thread, the harm rounds the bytes give
    std::size_t stop_at = 0;  ///< the question the stop callback says yes to; 0: no callback
    std::optional<std::chrono::milliseconds> deadline;  ///< from the start of restore()
};

/// Takes any bytes; gives the case they describe.
RestoreFuzzInput read_restore_fuzz_input(std::span<const std::uint8_t> bytes);

/// Takes any bytes; gives "" when restore() kept every promise, else what it broke: a bound it
/// states (harm rounds, questions to the stop callback, a deadline missed by more than 3 s), a
/// stop not giving the input back, an unchanged output that differs from the input, or harm by
/// the criteria of harm_criteria.h (self-intersections included). Exceptions from restore()
/// pass through: none is expected.
std::string restore_fuzz_case(std::span<const std::uint8_t> bytes);

}  // namespace resharp::test
