#include "resharp/io/atomic_file.h"

#include <gtest/gtest.h>

#include "io/io_test_support.h"
#include "resharp/io/mesh_io.h"

namespace resharp::io {
namespace {

TEST(AtomicFile, CommitMovesTheWholeFileIntoPlace) {
    const auto dir = test::scratch_dir();
    AtomicFile file(dir / "report.json");
    file.stream() << "{}\n";
    EXPECT_EQ(file.temporary_path().parent_path(), dir);
    EXPECT_FALSE(std::filesystem::exists(dir / "report.json"));
    file.commit();
    EXPECT_EQ(test::read_bytes(dir / "report.json"), "{}\n");
    EXPECT_EQ(test::files_in(dir), std::vector<std::string>{"report.json"});
}

TEST(AtomicFile, ExceptionBeforeCommitLeavesNoFileAndKeepsTheOldOne) {
    const auto dir = test::scratch_dir();
    test::write_bytes(dir / "old.txt", "old");
    EXPECT_THROW(write_atomically(dir / "old.txt",
                                  [](std::ostream& out) {
                                      out << "half a file";
                                      throw std::runtime_error("writer failed");
                                  }),
                 std::runtime_error);
    EXPECT_THROW(write_atomically(dir / "new.txt",
                                  [](std::ostream& out) {
                                      out << "half a file";
                                      throw std::runtime_error("writer failed");
                                  }),
                 std::runtime_error);
    EXPECT_EQ(test::files_in(dir), std::vector<std::string>{"old.txt"});
    EXPECT_EQ(test::read_bytes(dir / "old.txt"), "old");
}

TEST(AtomicFile, MissingDirectoryIsAWriteError) {
    const auto dir = test::scratch_dir();
    try {
        AtomicFile file(dir / "no" / "such" / "out.stl");
        FAIL() << "no exception";
    } catch (const WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("out.stl: cannot create a temporary file"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_TRUE(test::files_in(dir).empty());
}

TEST(AtomicFile, RenameOntoADirectoryFailsCleanly) {
    const auto dir = test::scratch_dir();
    std::filesystem::create_directory(dir / "taken.ply");
    std::filesystem::create_directory(dir / "taken.ply" / "child");
    AtomicFile file(dir / "taken.ply");
    file.stream() << "x";
    EXPECT_THROW(file.commit(), WriteError);
    EXPECT_EQ(test::files_in(dir), std::vector<std::string>{"taken.ply"});
}

TEST(WriteMesh, FailureMidWriteLeavesNoFile) {
    const auto dir = test::scratch_dir();
    const Mesh mesh = test::box_mesh();
    const std::vector<Vec3> too_few_normals(3, Vec3::UnitZ());
    try {
        write_mesh(dir / "out.ply", mesh, {}, {.vertex_normals = too_few_normals});
        FAIL() << "no exception";
    } catch (const WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("out.ply: vertex_normals has 3 values for 8 vertices"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(write_mesh(dir / "missing" / "out.stl", mesh), WriteError);
    EXPECT_TRUE(test::files_in(dir).empty());
}

}  // namespace
}  // namespace resharp::io
