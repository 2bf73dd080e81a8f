// Every hostile file under tests/data/bad/ must be refused by read_mesh with the exception,
// location and reason its line in MANIFEST.tsv names (make_bad_files.py writes both).

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "io/io_test_support.h"
#include "resharp/io/mesh_io.h"

namespace resharp::io {
namespace {

const std::filesystem::path kBadDir = std::filesystem::path(RESHARP_TEST_DATA_DIR) / "bad";

struct Expectation {
    std::string file;
    std::string kind;      ///< "parse" (ParseError) or "read" (ReadError without location)
    std::string location;  ///< "line N", "byte N", or "-"
    std::string reason;    ///< a substring of what()
};

std::vector<Expectation> load_manifest() {
    std::vector<Expectation> rows;
    std::ifstream in(kBadDir / "MANIFEST.tsv");
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        Expectation e;
        std::getline(fields, e.file, '\t');
        std::getline(fields, e.kind, '\t');
        std::getline(fields, e.location, '\t');
        std::getline(fields, e.reason);
        rows.push_back(e);
    }
    return rows;
}

std::string test_name(const ::testing::TestParamInfo<Expectation>& info) {
    std::string name = info.param.file;
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return name;
}

class BadFile : public ::testing::TestWithParam<Expectation> {};

TEST_P(BadFile, IsRefusedWithFileLocationAndReason) {
    const Expectation& e = GetParam();
    const std::filesystem::path path = kBadDir / e.file;
    try {
        read_mesh(path);
        FAIL() << "read_mesh accepted " << path;
    } catch (const ParseError& error) {
        EXPECT_EQ(e.kind, "parse") << error.what();
        EXPECT_EQ(error.path(), path.string());
        const std::string what = error.what();
        EXPECT_NE(what.find(path.string() + ": " + e.location + ": "), std::string::npos) << what;
        EXPECT_NE(what.find(e.reason), std::string::npos) << what;
    } catch (const ReadError& error) {
        EXPECT_EQ(e.kind, "read") << error.what();
        EXPECT_EQ(error.path(), path.string());
        EXPECT_NE(std::string(error.what()).find(e.reason), std::string::npos) << error.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Manifest, BadFile, ::testing::ValuesIn(load_manifest()), test_name);

TEST(BadFiles, ManifestCoversEveryFileAndAtLeastThirty) {
    std::set<std::string> listed;
    for (const Expectation& e : load_manifest()) listed.insert(e.file);
    std::set<std::string> present;
    for (const std::string& name : test::files_in(kBadDir)) {
        if (name != "MANIFEST.tsv" && name != "make_bad_files.py") present.insert(name);
    }
    // A missing-file expectation names a file that must not exist.
    listed.erase("does_not_exist.stl");
    EXPECT_EQ(listed, present);
    EXPECT_GE(present.size(), 30u);
}

}  // namespace
}  // namespace resharp::io
