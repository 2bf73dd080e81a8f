#pragma once
/// The expectations for tests/data/bad/, read from MANIFEST.tsv (written by make_bad_files.py).
/// Shared by the library test (tests/io) and the CLI test (tests/cli).

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace resharp::test {

struct BadFileExpectation {
    std::string file;
    std::string kind;      ///< "parse" (ParseError) or "read" (ReadError without location)
    std::string location;  ///< "line N", "byte N", or "-"
    std::string reason;    ///< a substring of the message
};

/// Names the case in test output (instead of GoogleTest's byte dump of the struct).
inline void PrintTo(const BadFileExpectation& e, std::ostream* out) { *out << e.file; }

/// tests/data/bad/
std::filesystem::path bad_files_dir();

/// Every row of MANIFEST.tsv.
std::vector<BadFileExpectation> load_bad_file_manifest();

/// The file name as a GoogleTest name (letters, digits and '_').
std::string test_name_for(const std::string& file);

}  // namespace resharp::test
