// libFuzzer target for restore() itself (not a reader): each input is one case of
// tests/support/restore_fuzz_case.h (a small simulated part, damaged as the bytes say); any
// broken promise is printed and aborts, so libFuzzer keeps the input as a crash.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/restore_fuzz_case.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string problem = resharp::test::restore_fuzz_case({data, size});
    if (!problem.empty()) {
        std::fprintf(stderr, "restore_fuzzer: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
