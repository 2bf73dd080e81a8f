// FacesInSweepOrder hands faces out in face_swept_before() order, skipping closed ones, without
// sorting them all; checked against a full sort on meshes whose faces share z levels (as faces
// on a grid's x and y dexels do), coincident vertices and duplicate faces.

#include "resharp/mesh/geometric_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace resharp {
namespace {

/// `count` faces over points on a coarse lattice (many equal z, y and x), a few coincident.
Mesh lattice_soup(std::size_t count, std::mt19937& random) {
    Mesh mesh;
    std::uniform_int_distribution<int> coordinate(0, 4);
    for (int i = 0; i < 60; ++i) {
        mesh.positions.emplace_back(coordinate(random), coordinate(random),
                                    0.5 * coordinate(random));
    }
    mesh.positions.push_back(mesh.positions[3]);  // coincident with vertex 3
    std::uniform_int_distribution<Index> vertex(0, static_cast<Index>(mesh.positions.size() - 1));
    while (mesh.triangles.size() < count) {
        const Triangle t{vertex(random), vertex(random), vertex(random)};
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
    }
    mesh.triangles.push_back(mesh.triangles[0]);  // a duplicate face
    return mesh;
}

std::vector<Index> fully_sorted(const Mesh& mesh, std::vector<Index> faces) {
    std::sort(faces.begin(), faces.end(), [&](Index f, Index g) {
        return face_swept_before(mesh, corners_in_sweep_order(mesh, f),
                                 corners_in_sweep_order(mesh, g), f, g);
    });
    return faces;
}

TEST(FacesInSweepOrder, HandsOutEveryFaceInSweepOrder) {
    std::mt19937 random(3);
    const Mesh mesh = lattice_soup(500, random);
    std::vector<Index> faces(mesh.face_count());
    std::iota(faces.begin(), faces.end(), Index{0});
    std::shuffle(faces.begin(), faces.end(), random);
    FacesInSweepOrder order(mesh, faces);
    std::vector<Index> handed;
    for (Index f = order.next([](Index) { return true; }); f != kNoIndex;
         f = order.next([](Index) { return true; }))
        handed.push_back(f);
    EXPECT_EQ(handed, fully_sorted(mesh, faces));
}

// As region growing uses it: each face handed out closes some later ones; each hand-out must be
// the first open face of a full sort at that moment.
TEST(FacesInSweepOrder, HandsOutTheFirstOpenFace) {
    std::mt19937 random(4);
    const Mesh mesh = lattice_soup(800, random);
    std::vector<Index> faces(mesh.face_count());
    std::iota(faces.begin(), faces.end(), Index{0});
    const std::vector<Index> sorted = fully_sorted(mesh, faces);
    std::vector<std::uint8_t> open(mesh.face_count(), 1);
    FacesInSweepOrder order(mesh, faces);
    auto is_open = [&](Index f) { return open[f] != 0; };
    std::uniform_int_distribution<Index> any_face(0, static_cast<Index>(mesh.face_count() - 1));
    std::size_t handed = 0;
    for (Index f = order.next(is_open); f != kNoIndex; f = order.next(is_open), ++handed) {
        const auto first_open = std::find_if(sorted.begin(), sorted.end(), is_open);
        ASSERT_NE(first_open, sorted.end());
        EXPECT_EQ(f, *first_open);
        open[f] = 0;
        for (int k = 0; k < 3; ++k) open[any_face(random)] = 0;
    }
    EXPECT_TRUE(std::none_of(faces.begin(), faces.end(), is_open));
    EXPECT_GT(handed, 50u);
}

TEST(FacesInSweepOrder, HandsOutNothingFromNoFaces) {
    const Mesh mesh;
    FacesInSweepOrder order(mesh, {});
    EXPECT_EQ(order.next([](Index) { return true; }), kNoIndex);
}

}  // namespace
}  // namespace resharp
