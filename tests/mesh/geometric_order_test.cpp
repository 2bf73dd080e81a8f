// FacesInSweepOrder hands faces out in face_swept_before() order, skipping closed ones, without
// sorting them all; checked against a full sort on meshes whose faces share z levels (as faces
// on a grid's x and y dexels do) or all lie on one (a flat face across the grid's z planes, one
// slab ordered run by run), coincident vertices and duplicate faces.

#include "resharp/mesh/geometric_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace resharp {
namespace {

/// `count` faces over points on a coarse lattice (many equal z, y and x; z = 0 for all where
/// `flat`), a few coincident.
Mesh lattice_soup(std::size_t count, std::mt19937& random, bool flat = false) {
    Mesh mesh;
    std::uniform_int_distribution<int> coordinate(0, 4);
    for (int i = 0; i < 60; ++i) {
        const double z = 0.5 * coordinate(random);
        mesh.positions.emplace_back(coordinate(random), coordinate(random), flat ? 0.0 : z);
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

/// Hands out every face of `mesh` as region growing asks for them, each hand-out closing
/// `closed_per_face` random faces (some later, some handed out already) and, every `sweep_every`
/// hand-outs, every other face still open (a region taking half a slab): each hand-out must be
/// the first open face of a full sort at that moment. Gives how many were handed out.
std::size_t check_first_open_faces(const Mesh& mesh, std::mt19937& random, int closed_per_face,
                                   std::size_t sweep_every) {
    std::vector<Index> faces(mesh.face_count());
    std::iota(faces.begin(), faces.end(), Index{0});
    const std::vector<Index> sorted = fully_sorted(mesh, faces);
    std::vector<std::uint8_t> open(mesh.face_count(), 1);
    FacesInSweepOrder order(mesh, faces);
    auto is_open = [&](Index f) { return open[f] != 0; };
    std::uniform_int_distribution<Index> any_face(0, static_cast<Index>(mesh.face_count() - 1));
    std::size_t handed = 0;
    for (Index f = order.next(is_open); f != kNoIndex; f = order.next(is_open)) {
        const auto first_open = std::find_if(sorted.begin(), sorted.end(), is_open);
        EXPECT_NE(first_open, sorted.end());
        if (first_open == sorted.end()) break;
        EXPECT_EQ(f, *first_open);
        open[f] = 0;
        for (int k = 0; k < closed_per_face; ++k) open[any_face(random)] = 0;
        if (++handed % sweep_every == 0) {
            for (std::size_t i = 0; i < open.size(); i += 2) open[i] = 0;
        }
    }
    EXPECT_TRUE(std::none_of(faces.begin(), faces.end(), is_open));
    return handed;
}

// As region growing uses it: each face handed out closes some later ones.
TEST(FacesInSweepOrder, HandsOutTheFirstOpenFace) {
    std::mt19937 random(4);
    const Mesh mesh = lattice_soup(800, random);
    EXPECT_GT(check_first_open_faces(mesh, random, 3, mesh.face_count()), 50u);
}

// One slab of 2,000 faces: ordered in runs of 16, 32, ... between hand-outs that close many.
TEST(FacesInSweepOrder, HandsOutTheFirstOpenFaceOfOneLevel) {
    std::mt19937 random(5);
    const Mesh mesh = lattice_soup(2000, random, true);
    EXPECT_GT(check_first_open_faces(mesh, random, 1, 40), 100u);
    EXPECT_GT(check_first_open_faces(mesh, random, 0, mesh.face_count()), 1000u);
}

TEST(FacesInSweepOrder, HandsOutNothingFromNoFaces) {
    const Mesh mesh;
    FacesInSweepOrder order(mesh, {});
    EXPECT_EQ(order.next([](Index) { return true; }), kNoIndex);
}

}  // namespace
}  // namespace resharp
