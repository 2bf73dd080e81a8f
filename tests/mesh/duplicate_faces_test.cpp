#include "resharp/mesh/duplicate_faces.h"

#include <gtest/gtest.h>

#include "support/simple_meshes.h"

namespace resharp {
namespace {

/// The box with copies of some faces among the others: duplicates at the end, in the middle,
/// and two in a row.
Mesh box_with_copies() {
    Mesh mesh = test::box_mesh();
    const std::vector<Triangle> t = mesh.triangles;
    mesh.triangles = {t[0], t[1], t[0], t[2], t[3], t[3], t[3]};
    for (std::size_t f = 4; f < t.size(); ++f) mesh.triangles.push_back(t[f]);
    mesh.triangles.push_back(t[5]);
    return mesh;
}

TEST(DuplicateFaces, DroppingInPlaceKeepsWhatKeepFacesKeepsAndPutsBackWhatItTook) {
    const Mesh mesh = box_with_copies();
    const DuplicateFaces found = find_duplicate_faces(mesh, build_connectivity(mesh));
    ASSERT_EQ(found.removed, 4u);
    Mesh dropped_from = mesh;
    const DroppedFaces dropped = drop_faces(dropped_from, found.kept);
    EXPECT_EQ(dropped_from.triangles, keep_faces(mesh, found.kept).triangles);
    EXPECT_EQ(dropped_from.positions, mesh.positions);
    EXPECT_EQ(dropped.index,
              (std::vector<Index>{2, 5, 6, static_cast<Index>(mesh.face_count() - 1)}));
    put_back_faces(dropped_from, dropped);
    EXPECT_EQ(dropped_from.triangles, mesh.triangles);
}

TEST(DuplicateFaces, NothingToDropChangesNothing) {
    Mesh mesh = test::box_mesh();
    std::vector<Index> all(mesh.face_count());
    for (Index f = 0; f < all.size(); ++f) all[f] = f;
    const DroppedFaces dropped = drop_faces(mesh, all);
    EXPECT_TRUE(dropped.index.empty());
    EXPECT_EQ(mesh.triangles, test::box_mesh().triangles);
    put_back_faces(mesh, dropped);
    EXPECT_EQ(mesh.triangles, test::box_mesh().triangles);
}

}  // namespace
}  // namespace resharp
