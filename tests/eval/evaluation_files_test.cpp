#include "resharp/eval/evaluation_files.h"

#include <gtest/gtest.h>

#include <sstream>

#include "resharp/core/errors.h"

namespace resharp::eval {
namespace {

// Two triangles over four vertices; the files below list them in another order.
const Mesh kInput{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)},
                  {{0, 1, 2}, {1, 3, 2}}};

/// `mesh` with `attributes` written as PLY and read back, as evaluate reads its files.
io::PlyMesh round_trip(const Mesh& mesh, const io::MeshAttributes& attributes) {
    std::ostringstream out;
    io::write_ply(out, mesh, io::Encoding::Ascii, attributes);
    return io::read_ply_with_properties(out.str(), "test.ply");
}

/// kInput's vertices in the order 3, 2, 1, 0.
Mesh reversed_input() {
    return {{kInput.positions[3], kInput.positions[2], kInput.positions[1], kInput.positions[0]},
            {{3, 2, 1}, {2, 0, 1}}};
}

TEST(EvaluationFiles, OracleIsMatchedToTheInputByPosition) {
    const std::vector<Vec3> normals{Vec3(0, 0, 2), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, -1)};
    const std::vector<std::int32_t> surfaces{13, 12, 11, 10};
    const io::PlyMesh ply =
        round_trip(reversed_input(), {.vertex_normals = normals, .vertex_surfaces = surfaces});
    const Oracle oracle = match_oracle(ply, "test.ply", kInput);
    EXPECT_EQ(oracle.surfaces, (std::vector<std::int32_t>{10, 11, 12, 13}));
    EXPECT_EQ(oracle.normals[0], Vec3(0, 0, -1));
    EXPECT_EQ(oracle.normals[3], Vec3(0, 0, 1));  // normalised
}

// An off-surface mesher's oracle also gives each vertex its surface point (sx, sy, sz).
TEST(EvaluationFiles, OracleSurfacePointsAreMatchedToo) {
    const std::vector<Vec3> normals(4, Vec3(0, 0, 1));
    const std::vector<std::int32_t> surfaces(4, 5);
    const std::vector<Vec3> points{Vec3(1, 1, 0.1), Vec3(0, 1, 0.1), Vec3(1, 0, 0.1),
                                   Vec3(0, 0, 0.1)};
    const io::PlyMesh ply = round_trip(
        reversed_input(),
        {.vertex_normals = normals, .vertex_surfaces = surfaces, .vertex_surface_points = points});
    const Oracle oracle = match_oracle(ply, "test.ply", kInput);
    ASSERT_EQ(oracle.surface_points.size(), 4u);
    EXPECT_EQ(oracle.surface_points[0], Vec3(0, 0, 0.1));
    EXPECT_EQ(oracle.surface_points[3], Vec3(1, 1, 0.1));
    const io::PlyMesh plain =
        round_trip(kInput, {.vertex_normals = normals, .vertex_surfaces = surfaces});
    EXPECT_TRUE(match_oracle(plain, "test.ply", kInput).surface_points.empty());
}

TEST(EvaluationFiles, OracleOfAnotherMeshIsRefused) {
    Mesh moved = reversed_input();
    moved.positions[0].z() = 0.5;  // input vertex 3 is not in this oracle
    const std::vector<Vec3> normals(4, Vec3(0, 0, 1));
    const std::vector<std::int32_t> surfaces(4, 0);
    const io::PlyMesh with =
        round_trip(moved, {.vertex_normals = normals, .vertex_surfaces = surfaces});
    try {
        match_oracle(with, "o.ply", kInput);
        FAIL() << "no error";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("input vertex 3 is not in the oracle o.ply"),
                  std::string::npos)
            << e.what();
    }
    const io::PlyMesh without = round_trip(kInput, {.vertex_normals = normals});
    EXPECT_THROW(match_oracle(without, "o.ply", kInput), ReadError);  // no 'surface'
}

TEST(EvaluationFiles, RestoredMeshStartsWithTheInputsVertices) {
    Mesh read = reversed_input();
    read.positions.insert(read.positions.begin() + 1, Vec3(0.6, 0.6, 0.2));  // a new vertex
    read.triangles = {{4, 3, 1}, {3, 0, 1}, {2, 4, 1}, {0, 2, 1}};           // faces through it
    const Mesh m = match_restored(read, "r.stl", kInput);
    ASSERT_EQ(m.vertex_count(), 5u);
    EXPECT_TRUE(std::equal(kInput.positions.begin(), kInput.positions.end(), m.positions.begin()));
    EXPECT_EQ(m.positions[4], Vec3(0.6, 0.6, 0.2));
    EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 4}, {1, 3, 4}, {2, 0, 4}, {3, 2, 4}}));
}

TEST(EvaluationFiles, RestoredMeshMissingAnInputVertexIsRefused) {
    const Mesh read{{kInput.positions[0], kInput.positions[1], kInput.positions[2]}, {{0, 1, 2}}};
    try {
        match_restored(read, "r.stl", kInput);
        FAIL() << "no error";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("r.stl: input vertex 3 is missing"), std::string::npos)
            << e.what();
    }
}

// The colours restore --segments writes decode to the roles they stand for.
TEST(EvaluationFiles, SegmentRolesDecodeFromFaceColours) {
    const Mesh three{kInput.positions, {{0, 1, 2}, {1, 3, 2}, {0, 3, 2}}};
    const std::vector<io::Rgb> colors{kCornerTriangleColor, {1, 2, 3}, kEdgeTriangleColor};
    const io::PlyMesh ply = round_trip(three, {.face_colors = colors});
    EXPECT_EQ(decode_segment_roles(ply, "s.ply", 3),
              (std::vector<BandRole>{BandRole::Corner, BandRole::None, BandRole::Edge}));
    EXPECT_THROW(decode_segment_roles(ply, "s.ply", 2), InvalidInput);
    const io::PlyMesh uncoloured = round_trip(three, {});
    EXPECT_THROW(decode_segment_roles(uncoloured, "s.ply", 3), ReadError);
}

}  // namespace
}  // namespace resharp::eval
