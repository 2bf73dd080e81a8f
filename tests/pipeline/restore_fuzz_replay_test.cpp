// The restore() fuzzer's committed cases (tests/fuzz/corpus/restore: the seeds and every input
// that once broke a promise), replayed on every build: each must come out with no problem.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "support/restore_fuzz_case.h"

namespace resharp {
namespace {

TEST(RestoreFuzzReplay, EveryCommittedCaseKeepsEveryPromise) {
    std::vector<std::filesystem::path> cases;
    for (const auto& entry : std::filesystem::directory_iterator(RESHARP_RESTORE_FUZZ_CORPUS)) {
        cases.push_back(entry.path());
    }
    std::sort(cases.begin(), cases.end());
    ASSERT_GE(cases.size(), 12u);
    for (const std::filesystem::path& path : cases) {
        SCOPED_TRACE(path.filename().string());
        std::ifstream file(path, std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), {});
        EXPECT_EQ(test::restore_fuzz_case(bytes), "");
    }
}

}  // namespace
}  // namespace resharp
