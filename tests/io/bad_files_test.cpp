// Every hostile file under tests/data/bad/ must be refused by read_mesh with the exception,
// location and reason its line in MANIFEST.tsv names (make_bad_files.py writes both).

#include <gtest/gtest.h>

#include <set>

#include "io/bad_file_manifest.h"
#include "io/io_test_support.h"
#include "resharp/io/mesh_io.h"

namespace resharp::io {
namespace {

using test::BadFileExpectation;

class BadFile : public ::testing::TestWithParam<BadFileExpectation> {};

TEST_P(BadFile, IsRefusedWithFileLocationAndReason) {
    const BadFileExpectation& e = GetParam();
    const std::filesystem::path path = test::bad_files_dir() / e.file;
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

INSTANTIATE_TEST_SUITE_P(Manifest, BadFile, ::testing::ValuesIn(test::load_bad_file_manifest()),
                         [](const auto& row) { return test::test_name_for(row.param.file); });

TEST(BadFiles, ManifestCoversEveryFileAndAtLeastThirty) {
    std::set<std::string> listed;
    for (const BadFileExpectation& e : test::load_bad_file_manifest()) listed.insert(e.file);
    std::set<std::string> present;
    for (const std::string& name : test::files_in(test::bad_files_dir())) {
        if (name != "MANIFEST.tsv" && name != "make_bad_files.py") present.insert(name);
    }
    listed.erase("does_not_exist.stl");  // names a file that must not exist
    EXPECT_EQ(listed, present);
    EXPECT_GE(present.size(), 30u);
}

}  // namespace
}  // namespace resharp::io
