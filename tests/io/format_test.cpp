#include "resharp/io/format.h"

#include <gtest/gtest.h>

#include "resharp/core/errors.h"

namespace resharp::io {
namespace {

TEST(Format, ExtensionNamesFormatInAnyCase) {
    EXPECT_EQ(format_from_path("a/b/part.stl"), MeshFormat::Stl);
    EXPECT_EQ(format_from_path("PART.STL"), MeshFormat::Stl);
    EXPECT_EQ(format_from_path("x.Obj"), MeshFormat::Obj);
    EXPECT_EQ(format_from_path("x.pLy"), MeshFormat::Ply);
    EXPECT_EQ(format_from_path("x.off"), MeshFormat::Off);
    EXPECT_EQ(format_from_path("x.stl.gz"), std::nullopt);
    EXPECT_EQ(format_from_path("stl"), std::nullopt);
}

TEST(Format, UnknownExtensionIsAReadErrorForReading) {
    try {
        format_for_reading("dir/model.step");
        FAIL() << "no exception";
    } catch (const ReadError& e) {
        EXPECT_STREQ(e.what(),
                     "dir/model.step: unknown extension '.step' (expected extension .stl, .obj, "
                     ".ply or .off)");
        EXPECT_EQ(e.path(), "dir/model.step");
    }
}

TEST(Format, UnknownExtensionIsAWriteErrorForWriting) {
    EXPECT_THROW(format_for_writing("out"), WriteError);
    EXPECT_EQ(format_for_writing("out.OFF"), MeshFormat::Off);
}

TEST(Format, NamesFormats) {
    EXPECT_STREQ(format_name(MeshFormat::Ply), "PLY");
    EXPECT_STREQ(format_name(MeshFormat::Stl), "STL");
}

}  // namespace
}  // namespace resharp::io
