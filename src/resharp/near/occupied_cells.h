#pragma once
/// The grid cells that hold a vertex of a mesh: which cells its mesher put a vertex in. A dual
/// mesher (surface nets, OpenVDB's volumeToMesh) puts one in every cell the surface crosses where
/// its samples tell; a crossed cell with none is one where they did not, and the vertex nearest it
/// stands for it (near/vertex_moves.h).

#include <array>
#include <cstdint>
#include <vector>

#include "resharp/mesh/geometry.h"
#include "resharp/near/vertex_placement.h"

namespace resharp {

class OccupiedCells {
public:
    /// Takes the vertices' places and the grid they were placed on (pitch > 0). Bound: a sort of
    /// the vertices' cells.
    OccupiedCells(const std::vector<Vec3>& positions, const Grid& grid);

    /// Whether the cell that holds x (its lower faces included) holds a vertex. Bound: a
    /// bisection of the cells.
    bool holds_vertex(const Vec3& x) const;

private:
    using Key = std::array<std::int64_t, 3>;
    Key key_of(const Vec3& x) const;

    Grid grid_;
    std::vector<Key> cells_;  ///< ascending, each once
};

}  // namespace resharp
