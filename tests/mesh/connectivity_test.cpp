#include "resharp/mesh/connectivity.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "support/simple_meshes.h"

namespace resharp {
namespace {

TEST(Connectivity, EveryHalfEdgeOfAClosedBoxHasAnOppositeTwin) {
    const Mesh mesh = test::box_mesh();
    const Connectivity c = build_connectivity(mesh);
    ASSERT_EQ(c.twin.size(), 36u);
    for (Index h = 0; h < 36; ++h) {
        ASSERT_EQ(c.edge_kind[h], EdgeKind::Manifold);
        const Index t = c.twin[h];
        ASSERT_NE(t, kNoIndex);
        EXPECT_EQ(c.twin[t], h);
        EXPECT_EQ(tail_vertex(mesh, t), head_vertex(mesh, h));
        EXPECT_EQ(head_vertex(mesh, t), tail_vertex(mesh, h));
        EXPECT_NE(face_of(t), face_of(h));
    }
}

TEST(Connectivity, RingsListEachIncidentFaceOnceInOrder) {
    const Mesh mesh = test::box_mesh();
    const Connectivity c = build_connectivity(mesh);
    std::size_t total = 0;
    for (Index v = 0; v < 8; ++v) {
        const auto ring = c.faces_around(v);
        total += ring.size();
        EXPECT_TRUE(std::is_sorted(ring.begin(), ring.end()));
        for (Index f : ring) {
            const Triangle& t = mesh.triangles[f];
            EXPECT_TRUE(t[0] == v || t[1] == v || t[2] == v);
        }
    }
    EXPECT_EQ(total, 36u);
}

// A strip of six quads along x, each cut in two: faces 2k and 2k + 1 between columns k and
// k + 1, bottom vertex of column k 2k, top 2k + 1. Each ring from the corner vertex 0 reaches
// two faces further along.
TEST(Connectivity, FacesWithinRingsGrowARingAtATime) {
    Mesh mesh;
    for (int k = 0; k <= 6; ++k) {
        mesh.positions.emplace_back(k, 0.0, 0.0);
        mesh.positions.emplace_back(k, 1.0, 0.0);
    }
    for (Index k = 0; k < 6; ++k) {
        mesh.triangles.push_back({2 * k, 2 * k + 2, 2 * k + 1});
        mesh.triangles.push_back({2 * k + 1, 2 * k + 2, 2 * k + 3});
    }
    const Connectivity c = build_connectivity(mesh);
    EXPECT_TRUE(faces_within_rings(mesh, c, {0}, 0).empty());
    EXPECT_EQ(faces_within_rings(mesh, c, {0}, 1), (std::vector<Index>{0}));
    EXPECT_EQ(faces_within_rings(mesh, c, {0}, 2), (std::vector<Index>{0, 1, 2}));
    EXPECT_EQ(faces_within_rings(mesh, c, {0}, 3), (std::vector<Index>{0, 1, 2, 3, 4}));
    EXPECT_EQ(faces_within_rings(mesh, c, {12, 0}, 1), (std::vector<Index>{0, 10, 11}));
}

TEST(Connectivity, ClassifiesBoundaryNonManifoldAndInconsistentEdges) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {1, 1, 1}};
    // Three faces on edge 0-1 (non-manifold); faces 3 and 4 share 2->5 in the same direction.
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 5, 1}, {2, 5, 3}};
    const Connectivity c = build_connectivity(mesh);
    EXPECT_EQ(c.edge_kind[0], EdgeKind::NonManifold);    // 0->1 in face 0
    EXPECT_EQ(c.edge_kind[9], EdgeKind::Inconsistent);   // 2->5 in face 3
    EXPECT_EQ(c.edge_kind[12], EdgeKind::Inconsistent);  // 2->5 in face 4
    EXPECT_EQ(c.edge_kind[7], EdgeKind::Boundary);       // 0->3 in face 1
    EXPECT_EQ(c.twin[0], kNoIndex);
}

// for_each_halfedge_without_twin() skips eight manifold kinds at a time: it must still visit
// exactly the half-edges without a twin, in order, within words and in the tail after the last
// full one: a box with one face taken out (33 half-edges, 3 on the hole), the same with every
// face reversed but one (inconsistent edges), and the closed box (none).
TEST(Connectivity, HalfEdgesWithoutATwinAreVisitedInOrder) {
    Mesh open = test::box_mesh();
    open.triangles.erase(open.triangles.begin() + 5);
    Mesh flipped = open;
    for (std::size_t f = 1; f < flipped.triangles.size(); ++f) {
        std::swap(flipped.triangles[f][1], flipped.triangles[f][2]);
    }
    std::size_t total = 0;
    for (const Mesh& mesh : {open, flipped, test::box_mesh()}) {
        const Connectivity c = build_connectivity(mesh);
        std::vector<Index> expected, visited;
        for (Index h = 0; h < c.twin.size(); ++h) {
            if (c.twin[h] == kNoIndex) expected.push_back(h);
        }
        for_each_halfedge_without_twin(c, [&](Index h) { visited.push_back(h); });
        EXPECT_EQ(visited, expected);
        total += expected.size();
    }
    EXPECT_GT(total, 3u);
}
}  // namespace
}  // namespace resharp
