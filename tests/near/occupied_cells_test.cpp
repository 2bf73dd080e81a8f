// OccupiedCells: which cells of a grid hold a vertex, on a grid off the origin, with points on
// cell faces, negative coordinates, far-off points and a mesh of one vertex per cell.

#include "resharp/near/occupied_cells.h"

#include <gtest/gtest.h>

#include <vector>

namespace resharp {
namespace {

const Grid kGrid{0.5, Vec3(0.1, -0.2, 0.3)};

TEST(OccupiedCells, ACellHoldsAVertexWhereOneLiesInIt) {
    const OccupiedCells cells({Vec3(0.35, -0.05, 0.55)}, kGrid);  // the cell [0.1, 0.6) x ...
    EXPECT_TRUE(cells.holds_vertex(Vec3(0.35, -0.05, 0.55)));
    EXPECT_TRUE(cells.holds_vertex(Vec3(0.59, 0.29, 0.79)));    // another point of the same cell
    EXPECT_FALSE(cells.holds_vertex(Vec3(0.61, -0.05, 0.55)));  // the next cell along x
    EXPECT_FALSE(cells.holds_vertex(Vec3(0.35, -0.21, 0.55)));  // the one below along y
    EXPECT_FALSE(cells.holds_vertex(Vec3(0.35, -0.05, 0.81)));  // and above along z
}

TEST(OccupiedCells, APointOnACellsLowerFaceIsInThatCell) {
    const OccupiedCells cells({Vec3(0.6, 0.3, 0.8)}, kGrid);  // a node of the grid
    EXPECT_TRUE(cells.holds_vertex(Vec3(0.8, 0.5, 1.0)));     // its cell lies above it
    EXPECT_FALSE(cells.holds_vertex(Vec3(0.5, 0.2, 0.7)));    // the cell below the node
}

TEST(OccupiedCells, NegativeAndFarOffCoordinatesKeepTheirCells) {
    const std::vector<Vec3> vertices = {Vec3(-3.05, -7.45, -0.01), Vec3(1e21, -1e21, 0.0)};
    const OccupiedCells cells(vertices, kGrid);
    EXPECT_TRUE(cells.holds_vertex(Vec3(-2.91, -7.21, -0.19)));
    EXPECT_FALSE(cells.holds_vertex(Vec3(-3.41, -7.21, -0.19)));
    EXPECT_TRUE(cells.holds_vertex(Vec3(1e21, -1e21, 0.0)));
    EXPECT_FALSE(cells.holds_vertex(Vec3(0.0, 0.0, 0.0)));
}

TEST(OccupiedCells, EveryVertexOfAGridOfThemIsFoundAndNoCellBetween) {
    std::vector<Vec3> vertices;
    for (int i = 0; i < 20; i += 2) {
        for (int j = 0; j < 20; j += 2) {
            for (int k = 0; k < 20; k += 2)
                vertices.push_back(kGrid.origin + kGrid.pitch * Vec3(i + 0.5, j + 0.25, k + 0.75));
        }
    }
    const OccupiedCells cells(vertices, kGrid);
    std::size_t held = 0;
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            for (int k = 0; k < 20; ++k) {
                const bool has = i % 2 == 0 && j % 2 == 0 && k % 2 == 0;
                const Vec3 centre = kGrid.origin + kGrid.pitch * Vec3(i + 0.5, j + 0.5, k + 0.5);
                EXPECT_EQ(cells.holds_vertex(centre), has) << i << " " << j << " " << k;
                held += has;
            }
        }
    }
    EXPECT_EQ(held, vertices.size());
}

}  // namespace
}  // namespace resharp
