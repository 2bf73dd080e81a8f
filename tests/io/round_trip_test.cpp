#include <gtest/gtest.h>

#include "io/io_test_support.h"
#include "resharp/io/mesh_io.h"
#include "resharp/io/ply.h"

namespace resharp::io {
namespace {

struct Case {
    const char* extension;
    Encoding encoding;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
    return std::string(info.param.extension + 1) +
           (info.param.encoding == Encoding::Binary ? "Binary" : "Ascii");
}

class RoundTrip : public ::testing::TestWithParam<Case> {
protected:
    // Writes `mesh`, reads it back and checks every corner; binary STL keeps floats only.
    void check(const Mesh& mesh) {
        const auto path = test::scratch_dir() / (std::string("mesh") + GetParam().extension);
        write_mesh(path, mesh, {.encoding = GetParam().encoding});
        // Binary STL stores floats; every other encoding keeps doubles exactly.
        const TriangleSoup read = read_mesh(path);
        if (path.extension() == ".stl" && GetParam().encoding == Encoding::Binary) {
            test::expect_same_geometry(read, mesh, test::to_float_precision);
        } else {
            test::expect_same_geometry(read, mesh, [](const Vec3& p) { return p; });
        }
        const std::string first = test::read_bytes(path);
        write_mesh(path, mesh, {.encoding = GetParam().encoding});
        EXPECT_EQ(test::read_bytes(path), first) << "output is not deterministic";
        EXPECT_EQ(test::files_in(path.parent_path()), std::vector<std::string>{path.filename()});
    }
};

TEST_P(RoundTrip, Box) { check(test::box_mesh(1.5, 2.25, 0.1)); }

TEST_P(RoundTrip, TorusOf100kTriangles) {
    const Mesh mesh = test::torus_mesh(250, 210);
    ASSERT_GE(mesh.face_count(), 100000u);
    check(mesh);
}

INSTANTIATE_TEST_SUITE_P(
    EveryFormat, RoundTrip,
    ::testing::Values(Case{".stl", Encoding::Binary}, Case{".stl", Encoding::Ascii},
                      Case{".ply", Encoding::Binary}, Case{".ply", Encoding::Ascii},
                      Case{".obj", Encoding::Ascii}, Case{".off", Encoding::Ascii}),
    case_name);

class AttributeRoundTrip : public ::testing::TestWithParam<Encoding> {};

TEST_P(AttributeRoundTrip, NormalsExactSurfacesAndColours) {
    const Mesh mesh = test::torus_mesh(12, 9);
    std::vector<Vec3> normals;
    std::vector<std::int32_t> surfaces;
    std::vector<Vec3> surface_points;
    std::vector<Rgb> vertex_colors;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        normals.push_back(
            Vec3(mesh.positions[v].x(), 1.0 / 3.0, -0.1 * static_cast<double>(v)).normalized());
        surfaces.push_back(static_cast<std::int32_t>(v * 7919) - 100000);
        surface_points.push_back(mesh.positions[v] / 3.0 + Vec3(0.1, -1e-17, 1e300));
        vertex_colors.push_back({std::uint8_t(v), std::uint8_t(255 - v), 128});
    }
    std::vector<Rgb> face_colors(mesh.face_count(), Rgb{1, 2, 3});
    face_colors.back() = {255, 0, 255};

    const auto path = test::scratch_dir() / "oracle.ply";
    write_mesh(path, mesh, {.encoding = GetParam()},
               {.vertex_normals = normals,
                .vertex_surfaces = surfaces,
                .vertex_surface_points = surface_points,
                .vertex_colors = vertex_colors,
                .face_colors = face_colors});
    const PlyMesh read = read_ply_with_properties(path);
    ASSERT_EQ(read.soup.points, mesh.positions);
    ASSERT_EQ(read.soup.triangles, mesh.triangles);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        EXPECT_EQ((*read.vertex_property("nx"))[v], normals[v].x());  // bit-exact
        EXPECT_EQ((*read.vertex_property("ny"))[v], normals[v].y());
        EXPECT_EQ((*read.vertex_property("nz"))[v], normals[v].z());
        EXPECT_EQ((*read.vertex_property("surface"))[v], surfaces[v]);
        EXPECT_EQ((*read.vertex_property("sx"))[v], surface_points[v].x());
        EXPECT_EQ((*read.vertex_property("sy"))[v], surface_points[v].y());
        EXPECT_EQ((*read.vertex_property("sz"))[v], surface_points[v].z());
        EXPECT_EQ((*read.vertex_property("green"))[v], vertex_colors[v].green);
    }
    EXPECT_EQ(read.face_property("blue")->front(), 3);
    EXPECT_EQ(read.face_property("red")->back(), 255);
}

INSTANTIATE_TEST_SUITE_P(BothEncodings, AttributeRoundTrip,
                         ::testing::Values(Encoding::Binary, Encoding::Ascii));

TEST(WriteMesh, AttributesOnlyForPly) {
    const Mesh mesh = test::box_mesh();
    const std::vector<std::int32_t> surfaces(mesh.vertex_count(), 1);
    const auto dir = test::scratch_dir();
    for (const char* name : {"a.stl", "a.obj", "a.off"}) {
        try {
            write_mesh(dir / name, mesh, {}, {.vertex_surfaces = surfaces});
            ADD_FAILURE() << "no WriteError for " << name;
        } catch (const WriteError& e) {
            EXPECT_NE(std::string(e.what()).find("only PLY stores"), std::string::npos);
        }
    }
    EXPECT_TRUE(test::files_in(dir).empty());
}

TEST(WriteMesh, RefusesUnwritableMeshes) {
    const auto dir = test::scratch_dir();
    Mesh bad_index = test::box_mesh();
    bad_index.triangles[3][1] = 8;
    EXPECT_THROW(write_mesh(dir / "i.obj", bad_index), WriteError);
    Mesh nan = test::box_mesh();
    nan.positions[2].y() = std::nan("");
    EXPECT_THROW(write_mesh(dir / "n.ply", nan), WriteError);
    EXPECT_THROW(write_mesh(dir / "e.off", Mesh{}), WriteError);
    EXPECT_THROW(write_mesh(dir / "x.step", test::box_mesh()), WriteError);
    EXPECT_TRUE(test::files_in(dir).empty());
}

}  // namespace
}  // namespace resharp::io
