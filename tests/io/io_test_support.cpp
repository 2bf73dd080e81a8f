#include "io/io_test_support.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numbers>

namespace resharp::test {
namespace {

/// This process's folder of scratch folders, one per test.
std::filesystem::path process_scratch_root() {
    return std::filesystem::temp_directory_path() /
           ("resharp_io_tests_" + std::to_string(::getpid()));
}

/// Removes the process's scratch folders when its tests end, so that test runs leave nothing
/// behind in the temporary folder.
class RemoveScratch : public ::testing::Environment {
public:
    void TearDown() override {
        std::error_code ignored;  // a folder another tool holds open is not a test failure
        std::filesystem::remove_all(process_scratch_root(), ignored);
    }
};

[[maybe_unused]] const ::testing::Environment* const kRemoveScratch =
    ::testing::AddGlobalTestEnvironment(new RemoveScratch);

}  // namespace

std::filesystem::path scratch_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir =
        process_scratch_root() / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::vector<std::string> files_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

Mesh torus_mesh(int nu, int nv) {
    Mesh mesh;
    const double pi = std::numbers::pi;
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * pi * i / nu;
            const double v = 2 * pi * j / nv;
            mesh.positions.emplace_back((3 + std::cos(v)) * std::cos(u),
                                        (3 + std::cos(v)) * std::sin(u), std::sin(v));
        }
    }
    const auto at = [&](int i, int j) { return static_cast<Index>((i % nu) * nv + (j % nv)); };
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return mesh;
}

void expect_parse_error(const std::function<void()>& read, const std::string& name,
                        const std::string& location, const std::string& reason) {
    try {
        read();
        ADD_FAILURE() << "no ParseError; expected " << location << ": " << reason;
    } catch (const ParseError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(name + ": "), std::string::npos) << what;
        EXPECT_NE(what.find(": " + location + ": "), std::string::npos) << what;
        EXPECT_NE(what.find(reason), std::string::npos) << what;
    }
}

Vec3 to_float_precision(const Vec3& p) {
    // Through volatile floats: GCC 12 at -O2 dropped a plain double(float(x)) round trip here.
    Vec3 rounded;
    for (Eigen::Index i = 0; i < 3; ++i) {
        const volatile float f = static_cast<float>(p[i]);
        rounded[i] = f;
    }
    return rounded;
}

void expect_same_geometry(const TriangleSoup& soup, const Mesh& mesh,
                          const std::function<Vec3(const Vec3&)>& round) {
    const Mesh read = weld(soup);
    ASSERT_EQ(read.face_count(), mesh.face_count());
    ASSERT_EQ(read.vertex_count(), mesh.vertex_count());
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const Vec3 expected = round(mesh.positions[mesh.triangles[f][k]]);
            ASSERT_EQ(read.positions[read.triangles[f][k]], expected)
                << "face " << f << " corner " << k << std::setprecision(17) << ": read "
                << read.positions[read.triangles[f][k]].transpose() << ", expected "
                << expected.transpose();
        }
    }
}

}  // namespace resharp::test
